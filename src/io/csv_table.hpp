// A small CSV table as people write them by hand or export from a spreadsheet: a header line, then
// one row per line; fields separated by commas, a field may be quoted ("a, b" and "" for a quote);
// a UTF-8 byte-order mark, blank lines and lines starting with '#' are skipped. Every cell keeps
// where it was, so a reader of the table can locate its errors file:line:column.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "io/input_error.hpp"

namespace fl {

struct CsvCell {
  std::string text;  // without the blanks and quotes around it
  SourceLocation where;
};

struct CsvTable {
  std::vector<CsvCell> header;
  std::vector<std::vector<CsvCell>> rows;  // each as long as the header
};

// Throws InputError located at the cell or line at fault: an unterminated quote, a row with more
// or fewer fields than the header, a header with an empty or repeated name, no header at all.
CsvTable parse_csv_table(std::string_view text, const std::string& file);

// A text written as one CSV cell: quoted (its quotes doubled) when it holds a comma, a quote or a
// line break, as itself otherwise.
std::string csv_cell(std::string_view text);

}  // namespace fl
