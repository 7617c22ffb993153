// What the readers of other instruments share (a phone's magnetometer, its accelerometer,
// Tracker's positions, a table's): how clearly a channel shows what the rig's estimator times,
// and the one channel chosen turned into a log of counts that estimator runs on.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hall_log/hall_log.hpp"
#include "hall_log/measurement_table.hpp"

namespace fl {

// A channel's spread: its median and its 0.5th and 99.5th percentiles (the extremes, a lone
// glitch left out). Empty fields (NaN) are left out; nullopt when none is left.
struct Spread {
  double low = 0.0;
  double median = 0.0;
  double high = 0.0;
};
std::optional<Spread> spread_of(const std::vector<double>& values);

// How clearly a channel swings: its largest excursion from its median (either way) against the
// median step between samples, its noise. Empty fields (NaN) are left out; 0 for fewer than three
// values.
double swing_clarity(const std::vector<double>& values);

// The index of the channel that swings clearest, of one or more.
std::size_t clearest(const std::vector<const std::vector<double>*>& channels);

// The channel as a log the rig's estimator reads: the values mapped by one linear map onto 1000
// to 61000 counts (the estimator's timing levels are fractions of the pulse height, so the map
// changes no time it finds), each sample at its time and line. Throws InputError, as
// hall_log_from_samples does, for no samples or times that do not increase.
HallLog log_of_signal(const Series& signal, const std::string& name);

// What was read into such a log, said as a log's reading says it: the instrument and its channel,
// the file's format ("phyphox", "tracker", "table"), the time column (`time`, of `table`) and the
// value column's name, its header and decimal commas.
void say_what_was_read(HallLog& log, const MeasurementTable& table, std::size_t time,
                       MeasurementFile instrument, std::string channel, std::string format,
                       std::string value_column);

}  // namespace fl
