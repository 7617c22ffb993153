#include "hall_log/instrument_signal.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/input_error.hpp"

namespace fl {

double swing_clarity(const std::vector<double>& all) {
  std::vector<double> values;
  for (double v : all)
    if (!std::isnan(v)) values.push_back(v);
  if (values.size() < 3) return 0.0;
  std::vector<double> steps;
  steps.reserve(values.size() - 1);
  for (std::size_t i = 1; i < values.size(); ++i)
    steps.push_back(std::fabs(values[i] - values[i - 1]));
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                   steps.end());
  const double noise = steps[steps.size() / 2];
  std::sort(values.begin(), values.end());
  const double median = values[values.size() / 2];
  const double low = values[values.size() / 200];
  const double high = values[values.size() - 1 - values.size() / 200];
  const double excursion = std::max(high - median, median - low);
  return excursion / std::max(noise, 1e-12 * std::max(1.0, std::fabs(median)));
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
                       std::string instrument, std::string channel, std::string format,
                       std::string value_column) {
  log.instrument = std::move(instrument);
  log.channel = std::move(channel);
  HallLogReading& r = log.reading;
  r.format = std::move(format);
  r.columns_from = "header";
  r.time_column = table.names[time];
  r.adc_column = std::move(value_column);
  const double unit_s = seconds_per_time_unit(table.names[time]);
  r.time_unit = unit_s == 1.0 ? "s" : unit_s == 1e-3 ? "ms" : "us";
  r.time_unit_from = "header";
  r.header_line = table.header_line;
  r.first_line = table.header_line;
  r.decimal_comma = table.decimal_comma;
}

}  // namespace fl
