#include "cli/log_options.hpp"

namespace fl::cli {

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

}  // namespace fl::cli
