#include "api/api_contract.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "api/api_fields.hpp"

namespace fl::api {
namespace {

using nlohmann::json;

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

// The parts of `text` split at `separator` outside brackets.
std::vector<std::string> split_outside_brackets(const std::string& text, char separator) {
  std::vector<std::string> parts;
  int depth = 0;
  std::string part;
  for (const char c : text) {
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == separator && depth == 0) {
      parts.push_back(trimmed(part));
      part.clear();
    } else {
      part += c;
    }
  }
  parts.push_back(trimmed(part));
  return parts;
}

const ApiObject* object_named(const std::string& name) {
  for (const ApiObject& o : api_declaration().objects)
    if (name == o.name) return &o;
  return nullptr;
}

const ApiAlias* alias_named(const std::string& name) {
  for (const ApiAlias& a : api_declaration().aliases)
    if (name == a.name) return &a;
  return nullptr;
}

std::string found(const json& value) {
  const std::string text = value.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

void check(const json& value, const std::string& type, const std::string& path,
           std::vector<std::string>& problems);

void check_object(const json& value, const ApiObject& object, const std::string& path,
                  std::vector<std::string>& problems) {
  if (!value.is_object()) {
    problems.push_back(
        fmt::format("{}: expected an object {}, found {}", path, object.name, found(value)));
    return;
  }
  std::set<std::string> declared;
  for (const ApiKey& k : object.keys) {
    declared.insert(k.name);
    const auto at = value.find(k.name);
    const std::string where = path + "." + k.name;
    if (at == value.end()) {
      if (!k.optional) problems.push_back(fmt::format("{}: declared, but not there", where));
    } else if (at->is_null()) {
      if (!k.nullable)
        problems.push_back(fmt::format("{}: null, but not declared nullable", where));
    } else {
      check(*at, k.type, where, problems);
    }
  }
  for (const auto& [name, ignored] : value.items())
    if (!declared.contains(name))
      problems.push_back(fmt::format("{}.{}: not declared for {} (src/api/api_fields.cpp)", path,
                                     name, object.name));
}

void check(const json& value, const std::string& type, const std::string& path,
           std::vector<std::string>& problems) {
  const std::string t = trimmed(type);
  const std::vector<std::string> alternatives = split_outside_brackets(t, '|');
  if (alternatives.size() > 1) {
    // A union of quoted texts or of numbers.
    for (const std::string& a : alternatives) {
      if (a.front() == '"' && value.is_string() && a == json(value.get<std::string>()).dump())
        return;
      if (a.front() != '"' && value.is_number() && std::stod(a) == value.get<double>()) return;
    }
    problems.push_back(fmt::format("{}: expected one of {}, found {}", path, t, found(value)));
    return;
  }
  if (t == "number" || t == "string" || t == "boolean" || t == "object") {
    const bool ok = (t == "number" && value.is_number()) || (t == "string" && value.is_string()) ||
                    (t == "boolean" && value.is_boolean()) || (t == "object" && value.is_object());
    if (!ok) problems.push_back(fmt::format("{}: expected a {}, found {}", path, t, found(value)));
    return;
  }
  if (t.ends_with("[]")) {
    if (!value.is_array()) {
      problems.push_back(fmt::format("{}: expected an array, found {}", path, found(value)));
      return;
    }
    for (std::size_t i = 0; i < value.size(); ++i)
      check(value[i], t.substr(0, t.size() - 2), fmt::format("{}[{}]", path, i), problems);
    return;
  }
  if (t.front() == '[') {
    const std::vector<std::string> items = split_outside_brackets(t.substr(1, t.size() - 2), ',');
    if (!value.is_array() || value.size() != items.size()) {
      problems.push_back(fmt::format("{}: expected {}, found {}", path, t, found(value)));
      return;
    }
    for (std::size_t i = 0; i < items.size(); ++i)
      check(value[i], items[i], fmt::format("{}[{}]", path, i), problems);
    return;
  }
  if (const ApiAlias* alias = alias_named(t)) return check(value, alias->type, path, problems);
  if (const ApiObject* object = object_named(t))
    return check_object(value, *object, path, problems);
  problems.push_back(fmt::format("{}: the type {} is not declared", path, t));
}

}  // namespace

std::vector<std::string> contract_problems(const json& value, const std::string& type,
                                           const std::string& path) {
  std::vector<std::string> problems;
  check(value, type, path, problems);
  return problems;
}

}  // namespace fl::api
