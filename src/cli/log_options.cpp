#include "cli/log_options.hpp"

#include <cmath>

#include "cli/option_quantity.hpp"
#include "io/input_error.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl::cli {

fl_estimator::Geometry parse_geometry(const std::string& text) {
  if (const auto geometry = geometry_from_option(text)) return *geometry;
  throw InputError({}, "--geometry: expected auto, one or pair, found \"" + text + "\"");
}

void add_log_reading_options(CLI::App& command, LogReadingOptions& options,
                             const std::string& with) {
  command.add_option("--columns", options.columns,
                     with +
                         "The log's fields in order, for a log without a header (or to "
                         "override it): t_us,adc, millis,sensorValue, _,t_ms,adc (_ skips a "
                         "field)");
  command.add_option("--rate", options.rate,
                     with +
                         "Sample rate (1kHz): time the samples by their count, for a log "
                         "without a time column (or whose times repeat)");
  command.add_option("--time-unit", options.time_unit,
                     with +
                         "Unit of the time column when its name gives none: us, ms or s "
                         "(default: the unit that makes the sample rate 20 Hz to 20 kHz)");
}

HallLogOptions log_reading(const LogReadingOptions& options) {
  HallLogOptions reading;
  reading.columns = options.columns;
  reading.time_unit = options.time_unit;
  if (!options.rate.empty()) {
    reading.rate_hz = option_quantity(options.rate, Dimension::kFrequency, "--rate");
    if (!(reading.rate_hz > 0.0) || !std::isfinite(reading.rate_hz))
      throw InputError({}, "--rate: expected a positive sample rate (for example 1kHz), found \"" +
                               options.rate + "\"");
  }
  return reading;
}

}  // namespace fl::cli
