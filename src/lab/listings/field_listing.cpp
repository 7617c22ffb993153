#include "lab/listings/field_listing.hpp"

#include <fmt/format.h>

#include "lab/logs/estimate_fields.hpp"
#include "lab/logs/log_table_fields.hpp"
#include "lab/run/summary_fields.hpp"

namespace fl {
namespace {

// A markdown cell: `|` would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string null_rule(const SummaryField& f) {
  return f.null_when == nullptr ? std::string("never") : cell(f.null_when);
}

std::string json_keys_table() {
  std::string out = "| key | unit | meaning | null when |\n| --- | --- | --- | --- |\n";
  for (const SummaryField& f : summary_fields()) {
    if (f.json == nullptr) continue;
    const std::string where = f.timing ? " (stdout and timing.json only: this machine's cost)" : "";
    out += fmt::format("| `{}` | {} | {}{} | {} |\n", f.json, f.unit, cell(f.meaning), where,
                       null_rule(f));
  }
  return out;
}

std::string sweep_columns_table() {
  std::string out = "| column | unit | meaning | empty when |\n| --- | --- | --- | --- |\n";
  for (const SummaryField& f : summary_fields()) {
    if (f.sweep == nullptr) continue;
    out += fmt::format("| `{}` | {} | {} | {} |\n", f.sweep, f.unit, cell(f.meaning), null_rule(f));
  }
  return out;
}

std::string python_type(const SummaryField& f) {
  std::string type = f.python_type != nullptr        ? f.python_type
                     : f.type == FieldType::kNumber  ? "float"
                     : f.type == FieldType::kInteger ? "int"
                     : f.type == FieldType::kFlag    ? "bool"
                     : f.type == FieldType::kText    ? "str"
                                                     : "dict[str, Any]";
  return f.null_when != nullptr ? "Optional[" + type + "]" : type;
}

std::string pyi_attributes() {
  std::string out;
  for (const SummaryField& f : summary_fields())
    if (f.python != nullptr) out += fmt::format("    {}: {}\n", f.python, python_type(f));
  return out;
}

std::string typescript_type(const SummaryField& f) {
  const std::string type = f.type == FieldType::kNumber || f.type == FieldType::kInteger ? "number"
                           : f.type == FieldType::kFlag                                  ? "boolean"
                           : f.type == FieldType::kText                                  ? "string"
                                                        : "Record<string, unknown>";
  return f.null_when != nullptr ? type + " | null" : type;
}

std::string typescript_summary() {
  std::string out =
      "/** A run's summary as the server sends it (summary.json's object; docs/cli.md). */\n"
      "export interface RunSummaryJson {\n";
  for (const SummaryField& f : summary_fields()) {
    if (f.json == nullptr || f.timing) continue;
    std::string doc = f.meaning;
    if (f.unit[0] != '\0') doc = fmt::format("[{}] {}", f.unit, doc);
    if (f.null_when != nullptr) doc += fmt::format("; null when {}", f.null_when);
    out += fmt::format("  /** {} */\n  {}{}: {};\n", doc, f.json, f.omit_when_null ? "?" : "",
                       typescript_type(f));
  }
  out += "}\n";
  return out;
}

std::string log_table_columns() {
  std::string out =
      "| column of estimates.csv | key of estimates.json | unit | meaning | empty or null when |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const LogTableField& f : log_table_fields()) {
    const auto name = [](const char* n) { return n != nullptr ? fmt::format("`{}`", n) : "—"; };
    out += fmt::format("| {} | {} | {} | {} | {} |\n", name(f.csv), name(f.json), f.unit,
                       cell(f.meaning), f.null_when == nullptr ? "never" : cell(f.null_when));
  }
  return out;
}

std::string estimate_json_keys() {
  std::string out = "| key | unit | meaning | null when |\n| --- | --- | --- | --- |\n";
  for (const EstimateField& f : estimate_fields())
    out += fmt::format("| `{}` | {} | {} | {} |\n", f.json, f.unit, cell(f.meaning),
                       f.null_when == nullptr ? "never" : cell(f.null_when));
  return out;
}

std::string estimate_attributes() {
  std::string out;
  for (const EstimateField& f : estimate_fields()) {
    if (f.python == nullptr) continue;
    const char* type = f.type == FieldType::kInteger ? "int"
                       : f.type == FieldType::kText  ? "str"
                       : f.type == FieldType::kFlag  ? "bool"
                                                     : "float";
    out += fmt::format("    {}: {}{}\n", f.python, f.null_when != nullptr ? "Optional[" : "",
                       std::string(type) + (f.null_when != nullptr ? "]" : ""));
  }
  return out;
}

}  // namespace

std::vector<FieldListing> field_listings() {
  return {
      {"run-json-keys", json_keys_table()},         {"log-table-columns", log_table_columns()},
      {"estimate-json-keys", estimate_json_keys()}, {"estimate-attributes", estimate_attributes()},
      {"sweep-run-columns", sweep_columns_table()}, {"run-summary-attributes", pyi_attributes()},
      {"run-summary-json", typescript_summary()}};
}

std::optional<std::string> with_listings(const std::string& file_text,
                                         const std::vector<FieldListing>& listings,
                                         std::string* problem) {
  std::string out;
  std::size_t at = 0;
  while (at < file_text.size()) {
    std::size_t end = file_text.find('\n', at);
    end = end == std::string::npos ? file_text.size() : end + 1;
    const std::string line = file_text.substr(at, end - at);
    out += line;
    at = end;
    const std::size_t mark = line.find("generated: ");
    if (mark == std::string::npos) continue;
    std::string name = line.substr(mark + 11);
    name = name.substr(0, name.find_first_of(" \n\r"));
    const FieldListing* listing = nullptr;
    for (const FieldListing& l : listings)
      if (l.name == name) listing = &l;
    if (listing == nullptr) {
      if (problem) *problem = "a block names no listing: \"" + name + "\"";
      return std::nullopt;
    }
    const std::size_t close = file_text.find("end generated", at);
    if (close == std::string::npos) {
      if (problem) *problem = "the block \"" + name + "\" has no \"end generated\" line";
      return std::nullopt;
    }
    out += listing->text;
    at = file_text.rfind('\n', close);
    at = at == std::string::npos || at < end ? end : at + 1;
  }
  return out;
}

}  // namespace fl
