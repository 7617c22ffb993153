// UTF-8, one character at a time: what the caption reader checks and the font draws.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fl {

struct Utf8Character {
  char32_t code = 0;      // the code point
  std::size_t bytes = 0;  // 1 to 4
};

// The character that starts at byte `at` of `text`, or nothing when the bytes there are not a
// well-formed one: a stray continuation byte, a sequence cut short, an overlong form, a surrogate
// or a value beyond U+10FFFF.
std::optional<Utf8Character> utf8_character_at(std::string_view text, std::size_t at);

// The text with every byte that is not part of a well-formed character written as \xNN (a file
// name that is not UTF-8, "bad\xff.csv", in a message or a JSON string, which must be UTF-8);
// well-formed text is returned as it is.
std::string escape_invalid_utf8(std::string_view text);

}  // namespace fl
