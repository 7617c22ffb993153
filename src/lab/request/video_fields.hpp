// The fields that say how a video's plate is tracked, shared by the requests that read a video
// (track_request, estimate_request): `roi` ("X,Y,W,H" in the video's pixels), `scale`
// (millimetres per pixel) and `plate_length` (the plate's length, for the scale).
#pragma once

#include <optional>
#include <string>

#include "lab/request/field_checks.hpp"
#include "tracking/plate_tracker.hpp"

namespace fl {

// The tracker's options from the fields, each problem added to `checks` at its field.
TrackOptions checked_track_options(const std::string& roi, const std::optional<double>& scale,
                                   const std::optional<QuantityInput>& plate_length,
                                   FieldChecks& checks);

}  // namespace fl
