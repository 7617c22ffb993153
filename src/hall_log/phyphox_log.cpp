#include "hall_log/phyphox_log.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include "io/input_error.hpp"
#include "text/describe.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

struct Table {
  std::vector<std::string> names;            // the header's fields, unquoted
  std::vector<std::vector<double>> columns;  // one per name
  std::vector<int> lines;                    // 1-based line of each row
  bool decimal_comma = false;
  int header_line = 0;
};

// A line's fields split on `separator`, each trimmed of spaces and quotes.
std::vector<std::string_view> split_fields(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == separator) {
      fields.push_back(trim(line.substr(start, i - start), " \"'"));
      start = i + 1;
    }
  }
  return fields;
}

// phyphox separates by tab, semicolon or comma: the header says which (its names hold none).
char separator_of(std::string_view header) {
  if (header.find('\t') != std::string_view::npos) return '\t';
  if (header.find(';') != std::string_view::npos) return ';';
  return ',';
}

std::optional<double> number_of(std::string_view field, bool decimal_comma) {
  std::string text(field);
  if (decimal_comma) std::replace(text.begin(), text.end(), ',', '.');
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

Table read_table(std::string_view text, const std::string& name) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  Table table;
  char separator = ',';
  int number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++number;
    if (line.empty()) continue;
    if (table.names.empty()) {
      separator = separator_of(line);
      table.header_line = number;
      for (std::string_view f : split_fields(line, separator)) table.names.emplace_back(f);
      table.columns.resize(table.names.size());
      continue;
    }
    // A decimal comma where the fields are not separated by commas.
    const bool decimal_comma = separator != ',' && line.find(',') != std::string_view::npos;
    table.decimal_comma = table.decimal_comma || decimal_comma;
    const std::vector<std::string_view> fields = split_fields(line, separator);
    if (fields.size() != table.names.size())
      throw InputError(SourceLocation(name, number),
                       describe("expected ", table.names.size(),
                                " fields as the header names, found ", fields.size()));
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const std::optional<double> value = number_of(fields[k], decimal_comma);
      if (!value)
        throw InputError(SourceLocation(name, number), "expected a number in the column \"" +
                                                           table.names[k] + "\", found \"" +
                                                           std::string(fields[k]) + "\"");
      table.columns[k].push_back(*value);
    }
    table.lines.push_back(number);
  }
  return table;
}

// How clearly a channel shows pulses: its largest excursion from its median (either way: a magnet
// may raise or lower a component) against the median step between samples, its noise.
double pulse_clarity(std::vector<double> values) {
  if (values.size() < 3) return 0.0;
  std::vector<double> steps;
  steps.reserve(values.size() - 1);
  for (std::size_t i = 1; i < values.size(); ++i)
    steps.push_back(std::fabs(values[i] - values[i - 1]));
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double noise = steps[steps.size() / 2];
  std::sort(values.begin(), values.end());
  const double median = values[values.size() / 2];
  const double low = values[values.size() / 200];
  const double high = values[values.size() - 1 - values.size() / 200];
  const double excursion = std::max(high - median, median - low);
  return excursion / std::max(noise, 1e-12 * std::max(1.0, std::fabs(median)));
}

struct Channel {
  std::string name;    // "x", "y", "z", "|B|"
  std::string column;  // the header's name ("" for |B| computed)
  std::vector<double> values;
};

std::vector<Channel> field_channels(const Table& t, const std::string& name) {
  std::array<std::optional<std::size_t>, 3> component;
  std::optional<std::size_t> absolute;
  for (std::size_t k = 0; k < t.names.size(); ++k) {
    const std::string lower = ascii_lower(t.names[k]);
    if (lower.rfind("absolute field", 0) == 0) absolute = k;
    for (std::size_t axis = 0; axis < 3; ++axis)
      if (lower.rfind(std::string("magnetic field ") + "xyz"[axis], 0) == 0) component[axis] = k;
  }
  std::vector<Channel> channels;
  for (std::size_t axis = 0; axis < 3; ++axis)
    if (component[axis])
      channels.push_back(
          {std::string(1, "xyz"[axis]), t.names[*component[axis]], t.columns[*component[axis]]});
  if (absolute) {
    channels.push_back({"|B|", t.names[*absolute], t.columns[*absolute]});
  } else if (component[0] && component[1] && component[2]) {
    Channel b{"|B|", "", {}};
    for (std::size_t i = 0; i < t.lines.size(); ++i)
      b.values.push_back(std::hypot(t.columns[*component[0]][i], t.columns[*component[1]][i],
                                    t.columns[*component[2]][i]));
    channels.push_back(std::move(b));
  }
  if (channels.empty())
    throw InputError(
        SourceLocation(name, 1),
        "expected phyphox's magnetometer columns (\"Magnetic field x (\xC2\xB5T)\", ... or "
        "\"Absolute field (\xC2\xB5T)\") in the header, found none");
  return channels;
}

}  // namespace

HallLog read_phyphox_magnetometer(std::string_view text, const std::string& name) {
  const Table table = read_table(text, name);
  if (table.names.empty() || ascii_lower(table.names[0]).rfind("time", 0) != 0)
    throw InputError(SourceLocation(name, 1),
                     "expected phyphox's header, its first column \"Time (s)\"");
  std::vector<Channel> channels = field_channels(table, name);
  const auto clearest =
      std::max_element(channels.begin(), channels.end(), [](const Channel& a, const Channel& b) {
        return pulse_clarity(a.values) < pulse_clarity(b.values);
      });
  const Channel& channel = *clearest;
  if (channel.values.empty()) throw InputError(SourceLocation(name, 1), "no samples");
  // The field in counts, by one linear map onto 1000 to 61000.
  const auto [lowest, highest] = std::minmax_element(channel.values.begin(), channel.values.end());
  const double span = *highest > *lowest ? *highest - *lowest : 1.0;
  std::vector<double> counts;
  counts.reserve(channel.values.size());
  for (double v : channel.values) counts.push_back(1000.0 + (v - *lowest) / span * 60000.0);
  HallLog log = hall_log_from_samples(table.columns[0], counts, name);
  for (std::size_t i = 0; i < log.line.size(); ++i) log.line[i] = table.lines[i];
  log.instrument = "phyphox magnetometer";
  log.channel = channel.name;
  log.reading.format = "phyphox";
  log.reading.columns_from = "header";
  log.reading.time_column = table.names[0];
  log.reading.adc_column = channel.column.empty() ? "|B| of the three components" : channel.column;
  log.reading.time_unit = "s";
  log.reading.time_unit_from = "header";
  log.reading.header_line = table.header_line;
  log.reading.first_line = table.header_line;
  log.reading.decimal_comma = table.decimal_comma;
  return log;
}

}  // namespace fl
