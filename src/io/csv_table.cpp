#include "io/csv_table.hpp"

#include <algorithm>
#include <cstddef>

#include "text/text.hpp"

namespace fl {
namespace {

// The fields of one line; `line_number` and `file` locate them.
std::vector<CsvCell> split_line(std::string_view line, int line_number, const std::string& file) {
  std::vector<CsvCell> cells;
  std::size_t i = 0;
  for (;;) {
    while (i < line.size() && is_blank(line[i])) ++i;
    CsvCell cell;
    cell.where = {file, line_number, static_cast<int>(i) + 1};
    if (i < line.size() && line[i] == '"') {
      std::size_t j = i + 1;
      for (;;) {
        if (j >= line.size())
          throw InputError(cell.where,
                           "expected a closing quote for the field that starts here, found the "
                           "end of the line (write a quote inside a field as \"\")");
        if (line[j] == '"') {
          if (j + 1 < line.size() && line[j + 1] == '"') {
            cell.text += '"';
            j += 2;
            continue;
          }
          ++j;
          break;
        }
        cell.text += line[j++];
      }
      while (j < line.size() && is_blank(line[j])) ++j;
      if (j < line.size() && line[j] != ',')
        throw InputError(
            {file, line_number, static_cast<int>(j) + 1},
            std::string("expected a comma after the quoted field, found '") + line[j] + "'");
      i = j;
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      std::size_t last = end;
      while (last > i && is_blank(line[last - 1])) --last;
      cell.text = std::string(line.substr(i, last - i));
      i = end;
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return cells;
}

}  // namespace

CsvTable parse_csv_table(std::string_view text, const std::string& file) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  CsvTable table;
  bool have_header = false;
  int line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    std::vector<CsvCell> cells = split_line(line, line_number, file);
    if (!have_header) {
      for (const CsvCell& c : cells) {
        if (c.text.empty())
          throw InputError(c.where, "expected a column name in the header, found an empty field");
        const auto same = std::find_if(cells.begin(), cells.end(),
                                       [&](const CsvCell& o) { return o.text == c.text; });
        if (&*same != &c)
          throw InputError(c.where, "the column \"" + c.text + "\" is named twice in the header (" +
                                        "first at column " + std::to_string(same->where.column) +
                                        "); give each column once");
      }
      table.header = std::move(cells);
      have_header = true;
      continue;
    }
    if (cells.size() != table.header.size())
      throw InputError(
          cells.size() > table.header.size()
              ? cells[table.header.size()].where
              : SourceLocation{file, line_number, static_cast<int>(line.size()) + 1},
          "expected " + std::to_string(table.header.size()) +
              " fields as the header names, found " + std::to_string(cells.size()) +
              (cells.size() > table.header.size()
                   ? "; remove the extra fields (quote a field that holds a comma: \"a, b\")"
                   : "; fill in the missing ones"));
    table.rows.push_back(std::move(cells));
  }
  if (!have_header)
    throw InputError({file, 0, 0}, "expected a header line naming the columns, found no line");
  return table;
}

std::string csv_cell(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace fl
