#include "hall_log/oscillation_log.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "hall_log/instrument_signal.hpp"
#include "hall_log/measurement_table.hpp"
#include "io/input_error.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

bool is_accelerometer(const RecognisedFile& file) {
  return file.kind == MeasurementFile::kPhyphoxCsv && file.instrument != "phyphox magnetometer";
}

// The columns that may hold the oscillation: positions (x, and Tracker's y: a camera may be held
// on its side), or the accelerometer's axes; each with the time column to its left.
struct Candidate {
  std::size_t time = 0;
  std::size_t column = 0;
  std::string channel;  // "x", "y", the axis
};

std::vector<Candidate> candidates(const MeasurementTable& t, const RecognisedFile& file) {
  std::vector<Candidate> out;
  std::optional<std::size_t> time;
  for (std::size_t k = 0; k < t.names.size(); ++k) {
    const std::string bare = bare_column_name(t.names[k]);
    if (is_time_column(bare)) {
      time = k;
      continue;
    }
    if (!time) continue;
    if (is_accelerometer(file)) {
      // "Acceleration x (m/s^2)", "Linear Acceleration x (m/s^2)"; not "Absolute acceleration".
      const std::string lower = ascii_lower(t.names[k]);
      const std::size_t at = lower.find("acceleration ");
      if (lower.rfind("absolute", 0) != 0 && at != std::string::npos && at + 13 < lower.size() &&
          std::string("xyz").find(lower[at + 13]) != std::string::npos)
        out.push_back({*time, k, std::string(1, lower[at + 13])});
    } else if (is_position_column(bare) ||
               (file.kind == MeasurementFile::kTracker && bare == "y")) {
      out.push_back({*time, k, t.names[k]});
    }
  }
  return out;
}

// The virtual sensor at the upper end of the swing: the part of the signal above its median plus
// 30 % of its upper swing; the rest of the time the baseline, 0.
std::vector<double> turns_at_upper_end(const std::vector<double>& values) {
  std::vector<double> sorted;
  for (double v : values)
    if (!std::isnan(v)) sorted.push_back(v);
  if (sorted.empty()) return values;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double high = sorted[sorted.size() - 1 - sorted.size() / 200];
  const double level = median + 0.3 * (high - median);
  std::vector<double> pulses;
  pulses.reserve(values.size());
  for (double v : values) pulses.push_back(std::isnan(v) ? v : std::max(0.0, v - level));
  return pulses;
}

std::string format_of(const RecognisedFile& file) {
  return file.kind == MeasurementFile::kTracker         ? "tracker"
         : file.kind == MeasurementFile::kPositionTable ? "table"
                                                        : "phyphox";
}

}  // namespace

bool is_oscillation_file(const RecognisedFile& file) {
  return file.kind == MeasurementFile::kTracker || file.kind == MeasurementFile::kPositionTable ||
         is_accelerometer(file);
}

HallLog read_oscillation_log(std::string_view text, const std::string& name,
                             const RecognisedFile& file) {
  const MeasurementTable table = read_measurement_table(text, name);
  const std::vector<Candidate> found = candidates(table, file);
  if (found.empty())
    throw InputError(SourceLocation(name, table.header_line),
                     is_accelerometer(file)
                         ? "expected phyphox's accelerometer columns (\"Acceleration x (m/s^2)\", "
                           "...) after its time, found none"
                         : "expected a position column (x, position, \"Position (m)\", x_mm) "
                           "after a time column, found none");
  const Candidate& chosen =
      *std::max_element(found.begin(), found.end(), [&](const Candidate& a, const Candidate& b) {
        return swing_clarity(table.columns[a.column]) < swing_clarity(table.columns[b.column]);
      });
  HallLog log = log_of_signal(
      series_of(table, chosen.time, turns_at_upper_end(table.columns[chosen.column])), name);
  say_what_was_read(log, table, chosen.time, file.instrument, chosen.channel, format_of(file),
                    table.names[chosen.column]);
  return log;
}

}  // namespace fl
