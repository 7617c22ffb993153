// The options that say how to read a Hall-sensor log, shared by the commands that read logs
// (estimate, compare --log); the requests' fields `columns`, `rate` and `time_unit`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace fl::cli {

// --columns, --rate and --time-unit as given ("" for an option not given).
struct LogReadingOptions {
  std::string columns;
  std::string rate;
  std::string time_unit;

  bool any() const { return !columns.empty() || !rate.empty() || !time_unit.empty(); }
};

// Adds the three options to a command; `with` starts each help text ("With --log: " or "").
void add_log_reading_options(CLI::App& command, LogReadingOptions& options,
                             const std::string& with);

}  // namespace fl::cli
