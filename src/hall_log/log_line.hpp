// One line of a Hall-sensor log as people capture it: the Arduino IDE's serial-monitor timestamp
// prefix ("12:34:56.789 -> "), fields separated by a delimiter (comma, semicolon, tab or runs of
// spaces), fields in quotes, and numbers with a decimal comma where the delimiter is not a comma.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace fl {

struct LogField {
  std::string_view text;  // without the blanks and quotes around it
  int column = 0;         // 1-based, in the line as captured (the IDE's prefix included)
};

// The length of the Arduino IDE serial monitor's "HH:MM:SS.mmm -> " prefix at the start of
// `line`, or 0 when there is none.
std::size_t ide_timestamp_prefix(std::string_view line);

// The delimiter a line uses: ';' or '\t' when present (a comma is then a decimal comma), else
// ',' when present, else 0 (runs of spaces).
char detect_delimiter(std::string_view line);

// The fields of `line` split at `delimiter` (0: runs of spaces or tabs); `offset` is added to
// each field's column (the length of a prefix already taken off the line).
std::vector<LogField> split_fields(std::string_view line, char delimiter, std::size_t offset = 0);

// A field as a finite number: "512", "+0.25", "1e3", and with a delimiter other than ',' also
// "0,25" (then *decimal_comma is set). False when the field is not a number.
bool parse_log_number(std::string_view text, char delimiter, double* out, bool* decimal_comma);

}  // namespace fl
