// A table of numbers another instrument writes, as a student hands it over: phyphox's CSVs,
// Tracker's exported data, a spreadsheet's or a logger's export. Lines before the header (Tracker's
// track name, its "#multi:" line) are skipped; the header is the first line whose first field
// names a time. Fields are separated by tabs, semicolons or commas (the header says which); numbers
// may use a decimal comma where the fields are not separated by commas, and scientific notation;
// an empty field (a frame Tracker has no mark for) is missing, not zero.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

struct MeasurementTable {
  std::vector<std::string> names;            // the header's fields, unquoted
  std::vector<std::vector<double>> columns;  // one per name; NaN where a field is empty
  std::vector<int> lines;                    // 1-based line of each row
  int header_line = 0;                       // 1-based
  bool decimal_comma = false;                // numbers written with a decimal comma
};

// Reads the table; `name` stands for the file in messages. Throws InputError, located at its
// line, for no header naming a time, a row with more fields than the header, or a field that is
// neither a number nor empty.
MeasurementTable read_measurement_table(std::string_view text, const std::string& name);

// A column's name in lower-case letters only, its unit left out: "Position (m)" -> "position",
// "x_mm" -> "xmm", "t [s]" -> "t".
std::string bare_column_name(std::string_view field);

// "t", "time", "timestamp", and "t_s", "t_ms", "t_us" (as bare_column_name gives them).
bool is_time_column(const std::string& bare);

// "x", "position", "pos", "displacement", "distance", alone or with a unit written without
// brackets ("x_mm" -> "xmm", "position_m"); as bare_column_name gives them.
bool is_position_column(const std::string& bare);

// The unit of a time column's name: "ms" for "t_ms", "Time (ms)"; "s" when the name gives none
// (Tracker's and phyphox's times are in seconds).
std::string time_column_unit(std::string_view name);

// The rows where the time column (`time`, scaled by its unit to seconds) and `values` (a column of
// the table, or one computed from its columns, one value per row) both hold a number, with each
// row's line.
struct Series {
  std::vector<double> t_s;
  std::vector<double> values;
  std::vector<int> lines;
};
Series series_of(const MeasurementTable& table, std::size_t time,
                 const std::vector<double>& values);

}  // namespace fl
