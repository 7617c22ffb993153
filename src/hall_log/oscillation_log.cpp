#include "hall_log/oscillation_log.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "hall_log/instrument_signal.hpp"
#include "hall_log/measurement_table.hpp"
#include "hall_log/periodic_motion.hpp"
#include "io/input_error.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

// The columns that may hold the oscillation: positions (x, and Tracker's y: a camera may be held
// on its side), or the accelerometer's axes; each with the time column to its left.
struct Candidate {
  std::size_t time = 0;
  std::size_t column = 0;
  std::string channel;  // "x", "y", the axis
};

std::vector<Candidate> candidates(const MeasurementTable& t, MeasurementFile kind) {
  std::vector<Candidate> out;
  std::optional<std::size_t> time;
  for (std::size_t k = 0; k < t.names.size(); ++k) {
    const std::string bare = bare_column_name(t.names[k]);
    if (is_time_column(bare)) {
      time = k;
      continue;
    }
    if (!time) continue;
    if (is_accelerometer(kind)) {
      // "Acceleration x (m/s^2)", "Linear Acceleration x (m/s^2)"; not "Absolute acceleration".
      const std::string lower = ascii_lower(t.names[k]);
      const std::size_t at = lower.find("acceleration ");
      if (lower.rfind("absolute", 0) != 0 && at != std::string::npos && at + 13 < lower.size() &&
          std::string("xyz").find(lower[at + 13]) != std::string::npos)
        out.push_back({*time, k, std::string(1, lower[at + 13])});
    } else if (is_position_column(bare) || (kind == MeasurementFile::kTracker && bare == "y")) {
      out.push_back({*time, k, t.names[k]});
    }
  }
  return out;
}

// The virtual sensor at the upper end of the swing: the part of the signal above its median plus
// 30 % of its upper swing; the rest of the time the baseline, 0.
std::vector<double> turns_at_upper_end(const std::vector<double>& values) {
  const std::optional<Spread> spread = spread_of(values);
  if (!spread) return values;
  const double level = spread->median + 0.3 * (spread->high - spread->median);
  std::vector<double> pulses;
  pulses.reserve(values.size());
  for (double v : values) pulses.push_back(std::isnan(v) ? v : std::max(0.0, v - level));
  return pulses;
}

std::string format_of(MeasurementFile kind) {
  return kind == MeasurementFile::kTracker         ? "tracker"
         : kind == MeasurementFile::kPositionTable ? "table"
                                                   : "phyphox";
}

}  // namespace

HallLog log_of_oscillation(const Series& oscillation, const std::string& name,
                           const std::string& unit, const Periodicity& periodicity) {
  Series pulses = oscillation;
  pulses.values = turns_at_upper_end(oscillation.values);
  HallLog log = log_of_signal(pulses, name);
  if (const Oscillation o = strongest_oscillation(oscillation, periodicity); o.amplitude > 0.0)
    log.half_swing = o.amplitude;
  log.swing_unit = unit;
  return log;
}

std::string column_unit(std::string_view header) {
  const std::string_view h = trim(header, " \t\"");
  for (const auto& [open, close] : {std::pair{'(', ')'}, std::pair{'[', ']'}}) {
    const std::size_t at = h.rfind(open);
    if (at != std::string_view::npos && !h.empty() && h.back() == close)
      return std::string(trim(h.substr(at + 1, h.size() - at - 2)));
  }
  const std::size_t under = h.rfind('_');
  if (under != std::string_view::npos) {
    const std::string suffix = ascii_lower(h.substr(under + 1));
    for (const char* unit : {"m", "cm", "mm", "px"})
      if (suffix == unit) return suffix;
  }
  return "";
}

HallLog read_oscillation_log(std::string_view text, const std::string& name, MeasurementFile kind) {
  const MeasurementTable table = read_measurement_table(text, name);
  const std::vector<Candidate> found = candidates(table, kind);
  if (found.empty())
    throw InputError(SourceLocation(name, table.header_line),
                     is_accelerometer(kind)
                         ? "expected phyphox's accelerometer columns (\"Acceleration x (m/s^2)\", "
                           "...) after its time, found none"
                         : "expected a position column (x, position, \"Position (m)\", x_mm) "
                           "after a time column, found none");
  std::vector<const std::vector<double>*> columns;
  for (const Candidate& c : found) columns.push_back(&table.columns[c.column]);
  const Candidate& chosen = found[clearest(columns)];
  const Series series = series_of(table, chosen.time, table.columns[chosen.column]);
  const Periodicity periodicity =
      require_periodic_motion(series, SourceLocation(name, table.header_line),
                              instrument_words(kind), "\"" + table.names[chosen.column] + "\"");
  HallLog log =
      log_of_oscillation(series, name, column_unit(table.names[chosen.column]), periodicity);
  say_what_was_read(log, table, chosen.time, kind, chosen.channel, format_of(kind),
                    table.names[chosen.column]);
  return log;
}

}  // namespace fl
