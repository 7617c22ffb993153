// Small text helpers shared by the readers of quantities, logs and sweep files.
#pragma once

#include <string>
#include <string_view>

namespace fl {

// Spaces, tabs and line ends: what trim() strips unless told otherwise.
inline constexpr std::string_view kWhitespace = " \t\r\n";

// Around a field of a log or table: blanks and quotes.
inline constexpr std::string_view kFieldPadding = " \t\r\"'";

// A space, a tab or a carriage return: what separates a line's fields.
inline constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// A number as given (12 significant digits), for messages.
std::string shown_number(double v);

// `s` with the letters A to Z in lower case (column names, units, words; other bytes as they are,
// whatever the locale).
std::string ascii_lower(std::string_view s);

// `s` without leading and trailing characters from `strip`.
std::string_view trim(std::string_view s, std::string_view strip = kWhitespace);

}  // namespace fl
