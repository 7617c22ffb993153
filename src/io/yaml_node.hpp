// Strict, located reading of YAML: every value knows the file, line, column and key path it came
// from, so each error reads "file:line:col: error: path: expected ..., found ...". Unknown keys
// are errors with a suggestion. yaml-cpp's marks are 0-based; we print them 1-based.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "core/units.hpp"
#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {

// Where a document came from: its file name, and the key paths that a request's `set` field
// replaced ("plate.thickness" -> the field "set" with "plate.thickness=5 kg"), so errors point at
// the right place.
struct YamlSource {
  std::string file;
  std::map<std::string, SourceLocation, std::less<>> overrides;
};

class YamlNode {
 public:
  YamlNode(YAML::Node node, std::shared_ptr<YamlSource> source, std::string path);

  const std::string& path() const { return path_; }
  SourceLocation location() const;
  [[noreturn]] void fail(std::string_view what) const;
  // The same, said in the catalogues (text/said.hpp).
  [[noreturn]] void fail(const Said& what) const;

  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool is_null() const { return node_.IsNull(); }

  // Maps. `allow_keys` fails on the first key not in the list, suggesting the closest one.
  void expect_map() const;
  void allow_keys(std::initializer_list<std::string_view> keys) const;
  bool has(std::string_view key) const;
  YamlNode at(std::string_view key) const;  // required key
  std::optional<YamlNode> find(std::string_view key) const;

  // Sequences.
  void expect_sequence() const;
  std::size_t size() const;
  YamlNode operator[](std::size_t index) const;

  // Scalars.
  std::string text() const;
  double quantity(Dimension dimension) const;
  Measured measured(Dimension dimension) const;
  double number() const;  // a plain number, no unit
  std::int64_t integer() const;
  bool boolean() const;

  const YAML::Node& raw() const { return node_; }

  // Replaces (or adds) the value at a dotted key path below this map, e.g. "plate.thickness",
  // with `value` read as YAML; errors about that key are then located at `where` (the override)
  // instead of a file line.
  void set_path(std::string_view dotted_path, std::string_view value, const SourceLocation& where);

 private:
  SourceLocation location_of_key(const std::string& key_path, const YAML::Mark& mark) const;

  YAML::Node node_;
  std::shared_ptr<YamlSource> source_;
  std::string path_;
};

// A loaded YAML file. Refuses files that do not exist, are larger than `max_bytes`, are empty or
// are not YAML, with a located InputError.
YamlNode load_yaml_file(const std::string& file, std::size_t max_bytes = 4u << 20);

// The same from text (tests, inline scenes); `name` stands in for the file name in errors.
YamlNode load_yaml_text(std::string_view text, const std::string& name);

}  // namespace fl
