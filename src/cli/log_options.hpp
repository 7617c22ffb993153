// The options that say how to read a Hall-sensor log and how many pulses a period has, shared by
// the commands that read logs (estimate, compare --log).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "estimator/period_estimator.h"
#include "io/hall_log_reader.hpp"

namespace fl::cli {

// --geometry: auto, one or pair. Throws InputError for anything else.
fl_estimator::Geometry parse_geometry(const std::string& text);

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

// The options as the reader takes them. Throws InputError for a rate that is not a positive
// frequency.
HallLogOptions log_reading(const LogReadingOptions& options);

}  // namespace fl::cli
