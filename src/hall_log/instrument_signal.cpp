#include "hall_log/instrument_signal.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/input_error.hpp"

namespace fl {

std::optional<Spread> spread_of(const std::vector<double>& all) {
  std::vector<double> values;
  for (double v : all)
    if (!std::isnan(v)) values.push_back(v);
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  return Spread{values[values.size() / 200], values[values.size() / 2],
                values[values.size() - 1 - values.size() / 200]};
}

double swing_clarity(const std::vector<double>& all) {
  std::vector<double> steps;
  double previous = std::nan("");
  for (double v : all) {
    if (std::isnan(v)) continue;
    if (!std::isnan(previous)) steps.push_back(std::fabs(v - previous));
    previous = v;
  }
  if (steps.size() < 2) return 0.0;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                   steps.end());
  const double noise = steps[steps.size() / 2];
  const Spread s = *spread_of(all);
  const double excursion = std::max(s.high - s.median, s.median - s.low);
  return excursion / std::max(noise, 1e-12 * std::max(1.0, std::fabs(s.median)));
}

std::size_t clearest(const std::vector<const std::vector<double>*>& channels) {
  std::size_t best = 0;
  double best_clarity = -1.0;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const double clarity = swing_clarity(*channels[i]);
    if (clarity > best_clarity) {
      best = i;
      best_clarity = clarity;
    }
  }
  return best;
}

HallLog log_of_signal(const Series& signal, const std::string& name) {
  if (signal.values.empty()) throw InputError(SourceLocation(name), "no samples");
  const auto [lowest, highest] = std::minmax_element(signal.values.begin(), signal.values.end());
  const double span = *highest > *lowest ? *highest - *lowest : 1.0;
  std::vector<double> counts;
  counts.reserve(signal.values.size());
  for (double v : signal.values) counts.push_back(1000.0 + (v - *lowest) / span * 60000.0);
  HallLog log = hall_log_from_samples(signal.t_s, counts, name);
  log.line = signal.lines;
  return log;
}

void say_what_was_read(HallLog& log, const MeasurementTable& table, std::size_t time,
                       MeasurementFile instrument, std::string channel, std::string format,
                       std::string value_column) {
  log.instrument = instrument;
  log.channel = std::move(channel);
  HallLogReading& r = log.reading;
  r.format = std::move(format);
  r.columns_from = "header";
  r.time_column = table.names[time];
  r.adc_column = std::move(value_column);
  r.time_unit = time_column_unit(table.names[time]);
  r.time_unit_from = "header";
  r.header_line = table.header_line;
  r.first_line = table.header_line;
  r.decimal_comma = table.decimal_comma;
}

}  // namespace fl
