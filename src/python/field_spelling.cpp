#include "python/field_spelling.hpp"

#include <map>

namespace fl::python {
namespace {

// Fields whose argument is not their last part.
const std::map<std::string, std::string, std::less<>>& exceptions() {
  static const std::map<std::string, std::string, std::less<>> names = {
      {"logs", "path"},
      {"follow.raw_log", "raw_log"},
      {"monte_carlo.draws", "mc"},
  };
  return names;
}

// A Python string literal.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'' || c == '\\') out += '\\';
    out += c;
  }
  return out + "'";
}

}  // namespace

std::string argument_of(const FieldMention& field) {
  std::string name;
  if (const auto it = exceptions().find(field.path); it != exceptions().end()) {
    name = it->second;
  } else {
    const std::size_t dot = field.path.rfind('.');
    name = field.path.substr(dot == std::string::npos ? 0 : dot + 1);
  }
  if (!field.value) return name;
  if (name == "set") {
    const std::size_t eq = field.value->find('=');
    if (eq != std::string::npos)
      return "set={" + quoted(field.value->substr(0, eq)) + ": " +
             quoted(field.value->substr(eq + 1)) + "}";
  }
  return name + "=" + quoted(*field.value);
}

std::string spelled(std::string_view text) {
  return spell_fields(text, argument_of);
}

}  // namespace fl::python
