#include "text/utf8.hpp"

namespace fl {

std::optional<Utf8Character> utf8_character_at(std::string_view text, std::size_t at) {
  if (at >= text.size()) return std::nullopt;
  const auto byte = static_cast<unsigned char>(text[at]);
  std::size_t extra = 0;
  char32_t c = 0;
  if (byte < 0x80) {
    c = byte;
  } else if ((byte & 0xE0) == 0xC0) {
    extra = 1;
    c = byte & 0x1Fu;
  } else if ((byte & 0xF0) == 0xE0) {
    extra = 2;
    c = byte & 0x0Fu;
  } else if ((byte & 0xF8) == 0xF0) {
    extra = 3;
    c = byte & 0x07u;
  } else {
    return std::nullopt;
  }
  if (at + extra >= text.size()) return std::nullopt;  // cut short
  for (std::size_t k = 1; k <= extra; ++k) {
    const auto next = static_cast<unsigned char>(text[at + k]);
    if ((next & 0xC0) != 0x80) return std::nullopt;
    c = (c << 6) | (next & 0x3Fu);
  }
  constexpr char32_t kSmallest[] = {0, 0x80, 0x800, 0x10000};
  if (c < kSmallest[extra] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return std::nullopt;
  return Utf8Character{c, extra + 1};
}

std::string escape_invalid_utf8(std::string_view text) {
  constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  std::size_t at = 0;
  while (at < text.size()) {
    if (const std::optional<Utf8Character> c = utf8_character_at(text, at)) {
      out.append(text.substr(at, c->bytes));
      at += c->bytes;
      continue;
    }
    const auto byte = static_cast<unsigned char>(text[at++]);
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
  return out;
}

}  // namespace fl
