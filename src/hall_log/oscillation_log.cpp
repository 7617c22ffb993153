#include "hall_log/oscillation_log.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/units.hpp"
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

// The channel averaged over a centred window of a twentieth of the period `period_s` (an odd
// number of samples, shrunk symmetrically at the ends): a phone's noise, sample to sample, would
// otherwise cross the timing level several times at each turn. A centred average shifts no turn,
// and dims a sinusoid's by sinc(1/20), 0.4 %. Gaps (NaN) stay gaps and are left out of the sums.
std::vector<double> averaged_over_period_twentieth(const Series& channel, double period_s) {
  const std::size_t n = channel.values.size();
  if (n < 2 || !(period_s > 0.0)) return channel.values;
  const double interval = (channel.t_s.back() - channel.t_s.front()) / static_cast<double>(n - 1);
  if (!(interval > 0.0)) return channel.values;
  const auto half = static_cast<std::size_t>(std::floor(0.5 * (period_s / 20.0) / interval));
  if (half == 0) return channel.values;
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(channel.values[i])) {
      out[i] = channel.values[i];
      continue;
    }
    const std::size_t reach = std::min({half, i, n - 1 - i});
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = i - reach; k <= i + reach; ++k) {
      if (std::isnan(channel.values[k])) continue;
      sum += channel.values[k];
      ++count;
    }
    out[i] = sum / count;
  }
  return out;
}

// "0.500 x", then " + 0.866 y" (or " - ...").
std::string weighted_axis(double w, const std::string& axis, bool first) {
  const char* sign = first ? (w < 0.0 ? "-" : "") : (w < 0.0 ? " - " : " + ");
  return fmt::format("{}{:.3f} {}", sign, std::fabs(w), axis);
}

// An accelerometer's axes combined along the plate's motion: the principal direction of their
// covariance (the first principal component of the samples, by power iteration from the clearest
// axis), so that a phone lying turned on the plate reads the plate's whole swing rather than its
// share on one axis (cos 60 deg = half on each of two). The weights, one per axis (those below
// 0.01, the noise's, left out); an empty list when the direction lies within 1 degree of one axis,
// which is then read as it is.
std::vector<double> direction_of_motion(const std::vector<const std::vector<double>*>& axes,
                                        std::size_t clearest_axis) {
  const std::size_t k = axes.size(), n = axes.front()->size();
  std::vector<double> mean(k, 0.0), cov(k * k, 0.0);
  std::size_t rows = 0;
  const auto complete = [&](std::size_t i) {
    for (const std::vector<double>* a : axes)
      if (std::isnan((*a)[i])) return false;
    return true;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!complete(i)) continue;
    ++rows;
    for (std::size_t a = 0; a < k; ++a) mean[a] += (*axes[a])[i];
  }
  if (rows < 2) return {};
  for (double& m : mean) m /= static_cast<double>(rows);
  for (std::size_t i = 0; i < n; ++i) {
    if (!complete(i)) continue;
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = 0; b < k; ++b)
        cov[a * k + b] += ((*axes[a])[i] - mean[a]) * ((*axes[b])[i] - mean[b]);
  }
  std::vector<double> w(k, 0.0), next(k);
  w[clearest_axis] = 1.0;
  for (int iteration = 0; iteration < 500; ++iteration) {
    double norm = 0.0;
    for (std::size_t a = 0; a < k; ++a) {
      next[a] = 0.0;
      for (std::size_t b = 0; b < k; ++b) next[a] += cov[a * k + b] * w[b];
      norm += next[a] * next[a];
    }
    if (!(norm > 0.0)) return {};
    for (std::size_t a = 0; a < k; ++a) w[a] = next[a] / std::sqrt(norm);
  }
  // A weight below 0.01 (half a degree) is the noise's, not the phone's tilt: left out.
  double kept = 0.0;
  for (double& v : w) {
    if (std::fabs(v) < 0.01) v = 0.0;
    kept += v * v;
  }
  for (double& v : w) v /= std::sqrt(kept);
  // Signed so that its largest weight is positive; one axis when within 1 degree of it.
  const std::size_t largest = static_cast<std::size_t>(
      std::max_element(w.begin(), w.end(),
                       [](double a, double b) { return std::fabs(a) < std::fabs(b); }) -
      w.begin());
  if (w[largest] < 0.0)
    for (double& v : w) v = -v;
  if (w[largest] >= std::cos(kPi / 180.0)) return {};
  return w;
}

// The axes' samples weighted by `w` and summed (NaN where any is missing).
Series along(const MeasurementTable& table, std::size_t time,
             const std::vector<const std::vector<double>*>& axes, const std::vector<double>& w) {
  std::vector<double> values(axes.front()->size(), 0.0);
  for (std::size_t a = 0; a < axes.size(); ++a)
    for (std::size_t i = 0; i < values.size(); ++i) values[i] += w[a] * (*axes[a])[i];
  return series_of(table, time, values);
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
  pulses.values = turns_at_upper_end(
      averaged_over_period_twentieth(oscillation, 1.0 / periodicity.strongest_hz));
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
  const std::size_t clearest_index = clearest(columns);
  const Candidate& chosen = found[clearest_index];
  // An accelerometer's axes (one time column) combine along the motion when it lies between them.
  std::vector<double> w;
  if (is_accelerometer(kind) && found.size() > 1 &&
      std::all_of(found.begin(), found.end(),
                  [&](const Candidate& c) { return c.time == chosen.time; }))
    w = direction_of_motion(columns, clearest_index);
  std::string channel = chosen.channel, column = table.names[chosen.column];
  if (!w.empty()) {
    channel.clear();
    column.clear();
    for (std::size_t a = 0; a < found.size(); ++a) {
      if (w[a] == 0.0) continue;
      channel += weighted_axis(w[a], found[a].channel, channel.empty());
      column += (column.empty() ? "" : ", ") + table.names[found[a].column];
    }
  }
  const Series series = w.empty() ? series_of(table, chosen.time, table.columns[chosen.column])
                                  : along(table, chosen.time, columns, w);
  const Periodicity periodicity =
      require_periodic_motion(series, SourceLocation(name, table.header_line),
                              instrument_said(kind), said("column-named", {arg("name", column)}));
  HallLog log =
      log_of_oscillation(series, name, column_unit(table.names[chosen.column]), periodicity);
  say_what_was_read(log, table, chosen.time, kind, channel, format_of(kind), column);
  return log;
}

}  // namespace fl
