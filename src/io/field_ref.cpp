#include "io/field_ref.hpp"

namespace fl {

std::string field_ref(std::string_view path) {
  std::string out(kFieldOpen);
  out += path;
  out += kFieldClose;
  return out;
}

std::string field_ref(std::string_view path, std::string_view value) {
  std::string out(kFieldOpen);
  out += path;
  out += '=';
  out += value;
  out += kFieldClose;
  return out;
}

std::optional<FieldMention> parse_field_ref(std::string_view text) {
  if (!text.starts_with(kFieldOpen) || !text.ends_with(kFieldClose)) return std::nullopt;
  const std::string_view inner =
      text.substr(kFieldOpen.size(), text.size() - kFieldOpen.size() - kFieldClose.size());
  if (inner.find(kFieldOpen) != std::string_view::npos ||
      inner.find(kFieldClose) != std::string_view::npos)
    return std::nullopt;
  FieldMention m;
  const std::size_t eq = inner.find('=');
  m.path = std::string(inner.substr(0, eq));
  if (eq != std::string_view::npos) m.value = std::string(inner.substr(eq + 1));
  if (m.path.empty()) return std::nullopt;
  return m;
}

std::string spell_fields(std::string_view text, const FieldSpelling& spelling) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find(kFieldOpen, at);
    if (open == std::string_view::npos) break;
    const std::size_t close = text.find(kFieldClose, open + kFieldOpen.size());
    if (close == std::string_view::npos) break;
    const std::optional<FieldMention> m =
        parse_field_ref(text.substr(open, close + kFieldClose.size() - open));
    out += text.substr(at, open - at);
    if (m) {
      out += spelling(*m);
    } else {
      out += text.substr(open, close + kFieldClose.size() - open);
    }
    at = close + kFieldClose.size();
  }
  out += text.substr(at);
  return out;
}

std::string plain_fields(std::string_view text) {
  return spell_fields(
      text, [](const FieldMention& m) { return m.value ? m.path + " " + *m.value : m.path; });
}

bool mentions_field(std::string_view text) {
  return text.find(kFieldOpen) != std::string_view::npos;
}

}  // namespace fl
