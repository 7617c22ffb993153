// The options that say how to read a Hall-sensor log and how many pulses a period has, shared by
// the commands that read logs (estimate, compare --log).
#pragma once

#include <string>

#include "estimator/period_estimator.h"
#include "io/hall_log_reader.hpp"

namespace fl::cli {

// --geometry: auto, one or pair. Throws InputError for anything else.
fl_estimator::Geometry parse_geometry(const std::string& text);

// --columns, --rate, --time-unit as the reader takes them ("" for an option not given). Throws
// InputError for a rate that is not a positive frequency.
HallLogOptions log_reading(const std::string& columns, const std::string& rate,
                           const std::string& time_unit);

}  // namespace fl::cli
