#include "api/api_listing.hpp"

#include <string>

#include <fmt/format.h>

#include "api/api_fields.hpp"

namespace fl::api {
namespace {

std::string typescript_types() {
  std::string out;
  for (const ApiAlias& a : api_declaration().aliases)
    out += fmt::format("/** {} */\nexport type {} = {};\n\n", a.meaning, a.name, a.type);
  for (const ApiObject& o : api_declaration().objects) {
    if (o.typed_elsewhere) continue;
    out += fmt::format("/** {} */\nexport interface {} {{\n", o.meaning, o.name);
    for (const ApiKey& k : o.keys) {
      std::string doc = k.meaning;
      if (k.unit[0] != '\0') doc = fmt::format("[{}] {}", k.unit, doc);
      out += fmt::format("  /** {} */\n  {}{}: {}{};\n", doc, k.name, k.optional ? "?" : "", k.type,
                         k.nullable ? " | null" : "");
    }
    out += "}\n\n";
  }
  out.pop_back();  // one blank line between types, none after the last
  return out;
}

// A markdown cell: `|` would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string key_tables() {
  std::string out;
  for (const ApiObject& o : api_declaration().objects) {
    if (o.typed_elsewhere) continue;
    out += fmt::format(
        "**`{}`**: {}\n\n| key | type | unit | null | meaning |\n"
        "| --- | --- | --- | --- | --- |\n",
        o.name, o.meaning);
    for (const ApiKey& k : o.keys)
      out += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", k.name, cell(k.type), k.unit,
                         k.nullable ? "yes" : "", cell(k.meaning));
    out += "\n";
  }
  out += "Aliases: ";
  bool first = true;
  for (const ApiAlias& a : api_declaration().aliases) {
    out += fmt::format("{}`{}` = `{}`", first ? "" : "; ", a.name, cell(a.type));
    first = false;
  }
  out += ".\n";
  return out;
}

}  // namespace

std::vector<FieldListing> api_listings() {
  return {{"web-api-types", typescript_types()}, {"web-api-keys", key_tables()}};
}

}  // namespace fl::api
