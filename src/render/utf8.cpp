#include "render/font.hpp"

#include "text/utf8.hpp"

namespace fl::render {

std::vector<char32_t> decode_utf8(std::string_view text) {
  std::vector<char32_t> out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    // What is not a character is drawn as U+FFFD, one byte at a time.
    const auto character = utf8_character_at(text, i);
    out.push_back(character ? character->code : char32_t{0xFFFD});
    i += character ? character->bytes : 1;
  }
  return out;
}

}  // namespace fl::render
