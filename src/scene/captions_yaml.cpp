#include "scene/captions_yaml.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "io/yaml_node.hpp"
#include "text/text.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

// The characters of well-formed UTF-8 (no overlong forms, surrogates or values past U+10FFFF),
// or nothing.
std::optional<std::size_t> utf8_length(std::string_view text) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < text.size(); ++count) {
    const auto character = utf8_character_at(text, i);
    if (!character) return std::nullopt;
    i += character->bytes;
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
    for (std::size_t open = c.text.find('{'); open != std::string::npos;
         open = c.text.find('{', open + 1)) {
      const std::size_t close = c.text.find('}', open);
      const std::string name =
          close == std::string::npos ? c.text.substr(open) : c.text.substr(open, close - open + 1);
      bool known = false;
      for (const std::string_view p : kCaptionPlaceholders) known = known || name == p;
      if (!known)
        text.fail(
            fmt::format("unknown placeholder \"{}\": a caption may name the run's {{mu_k}}, "
                        "{{material}}, {{T}}, {{temperature}} and {{spacing}}",
                        name));
    }
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
