#include "cli/field_spelling.hpp"

#include <map>

namespace fl::cli {
namespace {

// Fields whose flag is not "--" and their last part with hyphens.
const std::map<std::string, std::string, std::less<>>& exceptions() {
  static const std::map<std::string, std::string, std::less<>> flags = {
      {"logs", "LOG"},
      {"series", "SERIES.csv"},
      {"sweep", "SWEEP.yaml"},
      {"follow.port", "--follow"},
      {"follow.raw_log", "--log"},
      {"jobs", "-j"},
      {"monte_carlo.draws", "--mc"},
  };
  return flags;
}

}  // namespace

std::string flag_of(const FieldMention& field) {
  std::string flag;
  if (const auto it = exceptions().find(field.path); it != exceptions().end()) {
    flag = it->second;
  } else {
    const std::size_t dot = field.path.rfind('.');
    flag = "--" + field.path.substr(dot == std::string::npos ? 0 : dot + 1);
    for (char& c : flag)
      if (c == '_') c = '-';
  }
  if (!field.value) return flag;
  // A positional argument is its value alone.
  if (!flag.starts_with("-")) return *field.value;
  return flag + " " + *field.value;
}

std::string spelled(std::string_view text) {
  return spell_fields(text, flag_of);
}

}  // namespace fl::cli
