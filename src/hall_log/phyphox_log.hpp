// A phone's magnetometer beside the rig, as phyphox (RWTH Aachen's app) exports it, read as a log
// the rig's own estimator runs on: the magnets on the plate's ends pass the phone as they pass the
// Hall sensor, and each pass is a pulse on a field that holds the Earth's offset.
//
// phyphox writes one CSV per sensor in four forms (comma, tab or semicolon between fields; a
// decimal point, or a decimal comma where the fields are not separated by commas), its header
// quoted: "Time (s)","Magnetic field x (µT)","Magnetic field y (µT)","Magnetic field z (µT)" and
// "Absolute field (µT)" where the experiment gives it. The channel read is the one with the
// clearest pulses (the largest excursion from its median against its sample-to-sample noise) of
// the three components and |B| (computed when the file has no "Absolute field"); `channel` says
// which. The field's values become counts by one linear map (the estimator's timing levels are
// fractions of the pulse height, so the map changes no period).
#pragma once

#include <string>
#include <string_view>

#include "hall_log/hall_log.hpp"

namespace fl {

// Reads the text of a phyphox magnetometer CSV; `name` stands for the file in messages. Throws
// InputError, located at the line, for a header without a time or field column, a field that is
// not a number, a row of the wrong length, or times that do not increase.
HallLog read_phyphox_magnetometer(std::string_view text, const std::string& name);

}  // namespace fl
