#include "hall_log/log_line.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include "text/decimal.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

std::size_t ide_timestamp_prefix(std::string_view line) {
  // "HH:MM:SS.mmm -> ": digits at 0-1, 3-4, 6-7, 9-11; ':' ':' '.'; then " -> ".
  constexpr std::string_view kShape = "00:00:00.000 -> ";
  if (line.size() < kShape.size()) return 0;
  for (std::size_t i = 0; i < kShape.size(); ++i) {
    const bool ok = kShape[i] == '0' ? is_digit(line[i]) : line[i] == kShape[i];
    if (!ok) return 0;
  }
  return kShape.size();
}

char detect_delimiter(std::string_view line) {
  if (line.find(';') != line.npos) return ';';
  if (line.find('\t') != line.npos) return '\t';
  if (line.find(',') != line.npos) return ',';
  return 0;
}

std::vector<LogField> split_fields(std::string_view line, char delimiter, std::size_t offset) {
  std::vector<LogField> out;
  std::size_t i = 0;
  if (delimiter == 0) {
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      if (i >= line.size()) break;
      const std::size_t start = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      const std::string_view raw = line.substr(start, i - start);
      const std::size_t lead = raw.find_first_not_of(kFieldPadding);
      out.push_back({trim(raw, kFieldPadding),
                     static_cast<int>(offset + start + (lead == raw.npos ? 0 : lead)) + 1});
    }
    return out;
  }
  for (;;) {
    const std::size_t end = line.find(delimiter, i);
    const std::string_view raw =
        line.substr(i, end == std::string_view::npos ? line.npos : end - i);
    const std::size_t lead = raw.find_first_not_of(kFieldPadding);
    out.push_back({trim(raw, kFieldPadding),
                   static_cast<int>(offset + i + (lead == raw.npos ? 0 : lead)) + 1});
    if (end == std::string_view::npos) break;
    i = end + 1;
  }
  return out;
}

bool parse_log_number(std::string_view text, char delimiter, double* out, bool* decimal_comma) {
  text = trim(text, kFieldPadding);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  std::string swapped;
  const std::size_t comma = text.find(',');
  if (comma != text.npos) {
    // A decimal comma: one comma, not as the delimiter, between digits ("0,25", "512,0").
    if (delimiter == ',' || text.find(',', comma + 1) != text.npos || comma == 0 ||
        comma + 1 == text.size() || !is_digit(text[comma - 1]) || !is_digit(text[comma + 1]))
      return false;
    swapped = std::string(text);
    swapped[comma] = '.';
    text = swapped;
  }
  const auto [end, ec] = read_decimal(text.data(), text.data() + text.size(), *out);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(*out)) return false;
  if (comma != std::string_view::npos && decimal_comma != nullptr) *decimal_comma = true;
  return true;
}

}  // namespace fl
