// An oscillation another instrument followed, read as a log the rig's estimator runs on: the
// plate's positions (Tracker's exported track, a spreadsheet's or a logger's position column) or
// a phone lying on the plate, its accelerometer (a = -omega^2 x: the acceleration swings with the
// position, half a period out of phase, with the same period).
//
// The estimator times a magnet's turn at the rig's Hall sensor near one end of the travel; here a
// virtual sensor sits at that end of the recorded swing: the signal's part above its median plus
// 30 % of its upper swing (the 99.5th percentile) is the pulse, the rest the baseline. Each turn
// gives a pulse symmetric in time about the turning point, which the estimator places at the mid
// point of its level crossings, as it places a real magnet's turn; the periods, their scatter and
// mu_k follow as from a rig's log. Of several columns (Tracker's x and y, several tracks, the
// accelerometer's three axes) the one that swings clearest against its noise is read, and said.
// An amplitude that falls below 30 % of the largest swing gives no pulse there (the estimator
// counts a restart).
#pragma once

#include <string>
#include <string_view>

#include "hall_log/hall_log.hpp"
#include "hall_log/measurement_file.hpp"
#include "hall_log/measurement_table.hpp"
#include "hall_log/periodic_motion.hpp"

namespace fl {

// Reads a file recognised (`kind`) as Tracker's data, a position-time table, or a phyphox
// accelerometer CSV; `name` stands for the file in messages. Throws InputError, located at the
// line, for a table that cannot be read or holds no column to read.
HallLog read_oscillation_log(std::string_view text, const std::string& name, MeasurementFile kind);

// The same for positions (or accelerations) already in memory, each sample at its time and line:
// the virtual sensor's pulses at the upper end of the swing, as a log, with its amplitude in
// `unit` (its strongest oscillation's, from `periodicity`: periodicity_of the same samples, or
// what require_periodic_motion returned). Throws InputError as log_of_signal does.
HallLog log_of_oscillation(const Series& oscillation, const std::string& name,
                           const std::string& unit, const Periodicity& periodicity);

// The unit a column's header gives: "Position (m)" -> "m", "x [mm]" -> "mm", "x_mm" -> "mm",
// "Linear Acceleration x (m/s^2)" -> "m/s^2"; "" when it gives none ("x", Tracker's).
std::string column_unit(std::string_view header);

}  // namespace fl
