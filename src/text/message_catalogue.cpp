#include "text/message_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

namespace fl {
namespace {

bool is_id_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool is_id_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_';
}

std::string_view trim_spaces(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    out.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return out;
}

// A placeable read from `open` (a '{'): `{ $name }` or `{ "literal" }`; where it ends (after its
// '}'), or nullopt for anything else.
struct Placeable {
  bool variable = false;
  std::string text;  // the variable's name, or the literal
  std::size_t end = 0;
};

std::optional<Placeable> placeable_at(std::string_view pattern, std::size_t open) {
  std::size_t at = open + 1;
  const auto skip_spaces = [&] {
    while (at < pattern.size() && pattern[at] == ' ') ++at;
  };
  skip_spaces();
  if (at >= pattern.size()) return std::nullopt;
  Placeable p;
  if (pattern[at] == '$') {
    const std::size_t name = ++at;
    while (at < pattern.size() && is_id_char(pattern[at])) ++at;
    if (at == name) return std::nullopt;
    p.variable = true;
    p.text = std::string(pattern.substr(name, at - name));
  } else if (pattern[at] == '"') {
    const std::size_t close = pattern.find('"', at + 1);
    if (close == std::string_view::npos) return std::nullopt;
    p.text = std::string(pattern.substr(at + 1, close - at - 1));
    at = close + 1;
  } else {
    return std::nullopt;
  }
  skip_spaces();
  if (at >= pattern.size() || pattern[at] != '}') return std::nullopt;
  p.end = at + 1;
  return p;
}

// The pattern with its placeables filled; nullopt where one is not the lab's kind, or a brace
// stands alone.
std::optional<std::string> filled(std::string_view pattern,
                                  const std::map<std::string, std::string>& args) {
  std::string out;
  std::size_t at = 0;
  while (at < pattern.size()) {
    const char c = pattern[at];
    if (c == '}') return std::nullopt;
    if (c != '{') {
      out += c;
      ++at;
      continue;
    }
    const std::optional<Placeable> p = placeable_at(pattern, at);
    if (!p) return std::nullopt;
    if (!p->variable) {
      out += p->text;
    } else if (const auto arg = args.find(p->text); arg != args.end()) {
      out += arg->second;
    } else {
      out += "{$" + p->text + "}";
    }
    at = p->end;
  }
  return out;
}

}  // namespace

MessageCatalogue MessageCatalogue::parse(std::string_view ftl) {
  MessageCatalogue out;
  const std::vector<std::string_view> lines = lines_of(ftl);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    if (line.empty() || !is_id_start(line.front())) continue;  // comments, terms, continuations
    std::size_t end = 0;
    while (end < line.size() && is_id_char(line[end])) ++end;
    const std::string id(line.substr(0, end));
    std::string_view rest = trim_spaces(line.substr(end));
    if (rest.empty() || rest.front() != '=') continue;
    std::string pattern(trim_spaces(rest.substr(1)));
    bool attributes = false;
    // Continuation lines: indented, joined by a space (the report is HTML: a newline is one).
    for (; i + 1 < lines.size(); ++i) {
      const std::string_view next = lines[i + 1];
      if (next.empty() || (next.front() != ' ' && next.front() != '\t')) {
        if (!next.empty() || i + 2 >= lines.size() || lines[i + 2].empty() ||
            (lines[i + 2].front() != ' ' && lines[i + 2].front() != '\t'))
          break;
        continue;  // a blank line inside a multiline value
      }
      const std::string_view text = trim_spaces(next);
      if (text.starts_with('.')) attributes = true;
      if (attributes) continue;
      if (!pattern.empty()) pattern += ' ';
      pattern += text;
    }
    if (!pattern.empty() && filled(pattern, {})) out.messages_[id] = pattern;
  }
  return out;
}

std::optional<std::string> MessageCatalogue::format(
    std::string_view id, const std::map<std::string, std::string>& args) const {
  const auto it = messages_.find(std::string(id));
  if (it == messages_.end()) return std::nullopt;
  return filled(it->second, args);
}

}  // namespace fl
