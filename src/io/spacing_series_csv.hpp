// A series of periods measured at several roller spacings, as a CSV file a student writes: a
// header naming `spacing`, `period`, `period_err` and optionally `spacing_err` and `label` in
// any order, then one row per measurement. Values take units as in scene files ("89 mm",
// "0.79 s", "5ms"); a plain number is SI. Blank lines and lines starting with `#` are skipped
// (io/csv_table). The table `frictionlab estimate LOG...` writes is read as it is: its
// `rollers.spacing` is the spacing, rows whose `status` is not "ok" are left out, its notes and
// scene keys are read past (io/estimate_table_columns.hpp). So is a sweep's results.csv whose only
// axis is rollers.spacing: spacing_m, period_s and period_std_error_s are its spacing, period and
// dT, its points that failed or gave no period are left out. Every cell is checked where it
// stands: errors are located file:line:column.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/thick_plate_fit.hpp"
#include "io/input_error.hpp"

namespace fl {

// The columns a spacing series may have.
enum class SeriesColumn { kSpacing, kPeriod, kPeriodErr, kSpacingErr, kLabel };

struct SpacingSeriesRow {
  SpacingPeriod measurement;  // SI
  std::string label;          // empty without a label column
  int line = 0;               // 1-based line of the file
  // 1-based column of each cell, by SeriesColumn (0 for a column the file lacks).
  int columns[5] = {0, 0, 0, 0, 0};
};

struct SpacingSeries {
  std::string file;  // as the user named it
  int header_line = 0;
  bool has_spacing_err = false;
  bool has_label = false;
  std::vector<SpacingSeriesRow> rows;
  // Rows of an estimate table whose log gave no period, or of a sweep's results whose point
  // failed or gave no period.
  int rows_left_out = 0;
  bool sweep_results = false;  // the file is a sweep's results.csv
  // Cells read in a way the user may not have meant (a plain number of metres for a spacing of
  // 2 m or more), each located, for the command to print.
  std::vector<std::string> warnings;

  std::vector<SpacingPeriod> measurements() const;
  // Where a row's cell stands, for a message about it.
  SourceLocation at(std::size_t row, SeriesColumn column) const;
};

// Reads and checks the file: every value finite, spacings and periods and period errors > 0,
// spacing errors >= 0; at least 2 rows; at least two different spacings. Throws InputError
// located at the cell (or line, or file) at fault, saying what was expected, what was found and
// what to do.
SpacingSeries read_spacing_series(const std::string& path);

// The same for text already read; `file` names it in messages.
SpacingSeries parse_spacing_series(std::string_view text, const std::string& file);

}  // namespace fl
