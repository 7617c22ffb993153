#include "scene/captions_yaml.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "core/text.hpp"
#include "io/yaml_node.hpp"

namespace fl {
namespace {

// The code points of well-formed UTF-8 (no overlong forms, surrogates or values past U+10FFFF),
// or nothing.
std::optional<std::size_t> utf8_length(std::string_view text) {
  std::size_t count = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
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
    if (i + extra >= text.size()) return std::nullopt;  // cut short
    for (std::size_t k = 1; k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0) != 0x80) return std::nullopt;
      c = (c << 6) | (next & 0x3Fu);
    }
    constexpr char32_t kSmallest[] = {0, 0x80, 0x800, 0x10000};
    if (c < kSmallest[extra] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return std::nullopt;
    ++count;
    i += extra + 1;
  }
  return count;
}

double read_time(const YamlNode& node) {
  const double t = node.quantity(Dimension::kTime);
  if (!std::isfinite(t) || t < 0.0)
    node.fail(fmt::format("expected a simulated time of 0 s or later, found {}", node.text()));
  return t;
}

}  // namespace

std::vector<Caption> read_captions(const YamlNode& list) {
  list.expect_sequence();
  std::vector<Caption> captions;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YamlNode entry = list[i];
    entry.expect_map();
    entry.allow_keys({"at", "until", "text"});
    Caption c;
    const YamlNode at = entry.at("at");
    c.at = read_time(at);
    if (!captions.empty()) {
      const Caption& before = captions.back();
      if (c.at <= before.at)
        at.fail(
            fmt::format("expected a time after the previous caption's ({:g} s), found {}; "
                        "list the captions in the order they appear",
                        before.at, at.text()));
      if (before.until && *before.until > c.at)
        at.fail(
            fmt::format("the previous caption shows until {:g} s, past this one's start "
                        "({}); captions do not overlap: end it earlier or start this one later",
                        *before.until, at.text()));
    }
    if (auto until = entry.find("until")) {
      c.until = read_time(*until);
      if (*c.until <= c.at)
        until->fail(fmt::format("expected a time after the caption's `at` ({:g} s), found {}", c.at,
                                until->text()));
    }
    const YamlNode text = entry.at("text");
    c.text = std::string(trim(text.text()));
    if (c.text.empty()) text.fail("expected the caption's text, found none");
    const std::optional<std::size_t> characters = utf8_length(c.text);
    if (!characters) text.fail("expected UTF-8 text, found bytes that are not UTF-8");
    if (*characters > kCaptionMaxCharacters)
      text.fail(
          fmt::format("a caption holds at most {} characters (three lines of subtitle), "
                      "found {}; split it into two captions",
                      kCaptionMaxCharacters, *characters));
    captions.push_back(std::move(c));
  }
  return captions;
}

std::vector<Caption> load_captions_file(const std::string& file) {
  const YamlNode root = load_yaml_file(file);
  root.expect_map();
  root.allow_keys({"captions"});
  return read_captions(root.at("captions"));
}

}  // namespace fl
