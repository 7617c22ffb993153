#include "hall_log/measurement_table.hpp"

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>

#include "hall_log/log_columns.hpp"
#include "hall_log/log_line.hpp"
#include "io/input_error.hpp"
#include "text/describe.hpp"
#include "text/said.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

// A field as a number (a decimal comma where the fields are not separated by commas); NaN for an
// empty field; nullopt for one that is not a number.
std::optional<double> number_of(std::string_view field, char separator, bool* decimal_comma) {
  if (field.empty()) return std::numeric_limits<double>::quiet_NaN();
  double value = 0.0;
  if (!parse_log_number(field, separator, &value, decimal_comma)) return std::nullopt;
  return value;
}

bool is_header(std::string_view line) {
  const std::vector<LogField> fields = split_fields(line, detect_delimiter(line));
  return fields.size() >= 2 && is_time_column(bare_column_name(fields[0].text));
}

void add_row(MeasurementTable& table, std::string_view line, char separator, int number,
             const std::string& name) {
  const std::vector<LogField> fields = split_fields(line, separator);
  if (fields.size() > table.names.size())
    throw InputError(SourceLocation(name, number),
                     said("table-too-many-fields",
                          {arg("named", table.names.size()), arg("found", fields.size())}));
  for (std::size_t k = 0; k < table.names.size(); ++k) {
    const std::string_view field = k < fields.size() ? fields[k].text : std::string_view();
    const std::optional<double> value = number_of(field, separator, &table.decimal_comma);
    if (!value)
      throw InputError(SourceLocation(name, number, k < fields.size() ? fields[k].column : 0),
                       said("table-not-a-number",
                            {arg("column", table.names[k]), arg("found", std::string(field))}));
    table.columns[k].push_back(*value);
  }
  table.lines.push_back(number);
}

}  // namespace

MeasurementTable read_measurement_table(std::string_view text, const std::string& name) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  MeasurementTable table;
  char separator = ',';
  int number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(pos, end - pos), " \r");
    pos = end + 1;
    ++number;
    if (trim(line).empty()) continue;
    if (table.names.empty()) {
      if (!is_header(line)) continue;
      separator = detect_delimiter(line);
      table.header_line = number;
      for (const LogField& f : split_fields(line, separator)) table.names.emplace_back(f.text);
      table.columns.resize(table.names.size());
      continue;
    }
    add_row(table, line, separator, number, name);
  }
  if (table.names.empty()) throw InputError(SourceLocation(name, 1), said("table-no-header"));
  return table;
}

std::string bare_column_name(std::string_view field) {
  std::string name;
  for (char c : field) {
    if (c == '(' || c == '[') break;
    if (std::isalpha(static_cast<unsigned char>(c)))
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return name;
}

bool is_time_column(const std::string& n) {
  return n == "t" || n == "time" || n == "ts" || n == "tms" || n == "tus" || n == "timestamp";
}

bool is_position_column(const std::string& n) {
  for (std::string_view base : {"x", "position", "pos", "displacement", "distance"}) {
    if (n == base) return true;
    for (std::string_view unit : {"m", "cm", "mm", "px"})
      if (n.size() == base.size() + unit.size() && n.rfind(base, 0) == 0 &&
          std::string_view(n).substr(base.size()) == unit)
        return true;
  }
  return false;
}

std::string time_column_unit(std::string_view name) {
  const std::optional<ColumnName> column = column_name(name);
  return column && !column->unit.empty() ? column->unit : "s";
}

Series series_of(const MeasurementTable& table, std::size_t time,
                 const std::vector<double>& values) {
  Series s;
  const double scale = seconds_per(time_column_unit(table.names[time]));
  for (std::size_t i = 0; i < table.lines.size(); ++i) {
    const double t = table.columns[time][i];
    const double v = values[i];
    if (std::isnan(t) || std::isnan(v)) continue;
    s.t_s.push_back(t * scale);
    s.values.push_back(v);
    s.lines.push_back(table.lines[i]);
  }
  return s;
}

}  // namespace fl
