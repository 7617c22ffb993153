#include "io/yaml_node.hpp"

#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include "io/suggest.hpp"
#include "io/text_file.hpp"

namespace fl {
namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& file) {
  SourceLocation where{file, 0, 0};
  if (mark.line >= 0) where.line = mark.line + 1;
  if (mark.column >= 0) where.column = mark.column + 1;
  return where;
}

std::string join_path(const std::string& parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return parent + "." + std::string(key);
}

std::string found_text(const YAML::Node& node) {
  if (node.IsScalar()) return "\"" + node.Scalar() + "\"";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "nothing";
}

}  // namespace

YamlNode::YamlNode(YAML::Node node, std::shared_ptr<YamlSource> source, std::string path)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)) {}

SourceLocation YamlNode::location_of_key(const std::string& key_path,
                                         const YAML::Mark& mark) const {
  // A value the command line replaced is located there; so is everything below it.
  for (const auto& [overridden, where] : source_->overrides) {
    if (key_path == overridden || key_path.starts_with(overridden + ".") ||
        key_path.starts_with(overridden + "["))
      return where;
  }
  return location_of(mark, source_->file);
}

SourceLocation YamlNode::location() const {
  return location_of_key(path_, node_.Mark());
}

void YamlNode::fail(std::string_view what) const {
  throw InputError(location(),
                   path_.empty() ? std::string(what) : path_ + ": " + std::string(what));
}

void YamlNode::fail(const Said& what) const {
  const std::string text = english(what);
  throw InputError(location(), path_.empty() ? text : path_ + ": " + text, what);
}

void YamlNode::expect_map() const {
  if (!node_.IsMap()) fail("expected a map of keys, found " + found_text(node_));
}

void YamlNode::allow_keys(std::initializer_list<std::string_view> keys) const {
  expect_map();
  std::vector<std::string> seen;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar())
      throw InputError(location_of_key(path_, entry.first.Mark()),
                       (path_.empty() ? std::string() : path_ + ": ") +
                           "a key must be a plain word, found " + found_text(entry.first));
    const std::string key = entry.first.Scalar();
    const SourceLocation where = location_of_key(join_path(path_, key), entry.first.Mark());
    for (const std::string& earlier : seen) {
      if (earlier == key)
        throw InputError(where, join_path(path_, key) + ": the key is given twice; keep one");
    }
    seen.push_back(key);
    bool known = false;
    for (const std::string_view allowed : keys) known = known || allowed == key;
    if (known) continue;
    std::string message = join_path(path_, key) + ": unknown key";
    const std::string suggestion = closest_match(key, {keys.begin(), keys.size()});
    if (!suggestion.empty()) {
      message += "; did you mean '" + suggestion + "'?";
    } else {
      message += "; the keys here are:";
      for (const std::string_view allowed : keys) message += " " + std::string(allowed);
    }
    throw InputError(where, message);
  }
}

bool YamlNode::has(std::string_view key) const {
  return node_.IsMap() && node_[std::string(key)].IsDefined();
}

YamlNode YamlNode::at(std::string_view key) const {
  expect_map();
  const YAML::Node child = node_[std::string(key)];
  if (!child.IsDefined()) fail("the key '" + std::string(key) + "' is required but missing");
  return YamlNode(child, source_, join_path(path_, key));
}

std::optional<YamlNode> YamlNode::find(std::string_view key) const {
  expect_map();
  const YAML::Node child = node_[std::string(key)];
  if (!child.IsDefined() || child.IsNull()) return std::nullopt;
  return YamlNode(child, source_, join_path(path_, key));
}

void YamlNode::expect_sequence() const {
  if (!node_.IsSequence()) fail("expected a list, found " + found_text(node_));
}

std::size_t YamlNode::size() const {
  expect_sequence();
  return node_.size();
}

YamlNode YamlNode::operator[](std::size_t index) const {
  expect_sequence();
  return YamlNode(node_[index], source_, path_ + "[" + std::to_string(index) + "]");
}

std::string YamlNode::text() const {
  if (!node_.IsScalar()) fail("expected a text, found " + found_text(node_));
  return node_.Scalar();
}

double YamlNode::quantity(Dimension dimension) const {
  if (!node_.IsScalar())
    fail("expected " + dimension_with_article(dimension) + ", found " + found_text(node_));
  try {
    return parse_quantity(node_.Scalar(), dimension, "");
  } catch (const UnitError& e) {
    // parse_quantity's message starts with the (empty) quantity name and ": ".
    fail(std::string(e.what()).substr(2));
  }
}

Measured YamlNode::measured(Dimension dimension) const {
  if (!node_.IsScalar())
    fail("expected " + dimension_with_article(dimension) + " with its uncertainty, found " +
         found_text(node_));
  try {
    return parse_measured(node_.Scalar(), dimension, "");
  } catch (const UnitError& e) {
    fail(std::string(e.what()).substr(2));
  }
}

double YamlNode::number() const {
  return quantity(Dimension::kDimensionless);
}

std::int64_t YamlNode::integer() const {
  const double value = number();
  if (std::floor(value) != value || std::fabs(value) > 9.0e15)
    fail("expected a whole number, found " + found_text(node_));
  return static_cast<std::int64_t>(value);
}

bool YamlNode::boolean() const {
  const std::string t = text();
  if (t == "true" || t == "yes" || t == "on") return true;
  if (t == "false" || t == "no" || t == "off") return false;
  fail("expected true or false, found " + found_text(node_));
}

void YamlNode::set_path(std::string_view dotted_path, std::string_view value,
                        const SourceLocation& where) {
  if (dotted_path.empty()) throw InputError(where, "expected key.path=value, found no key");
  YAML::Node parsed;
  try {
    parsed = YAML::Load(std::string(value));
  } catch (const YAML::Exception& e) {
    throw InputError(where, "the value is not valid YAML: " + e.msg);
  }
  if (!node_.IsMap()) fail("expected a map of keys, found " + found_text(node_));
  YAML::Node current;
  current.reset(node_);
  std::string walked = path_;
  std::string_view rest = dotted_path;
  while (true) {
    const std::size_t dot = rest.find('.');
    const std::string key(rest.substr(0, dot));
    if (key.empty()) throw InputError(where, "the key path has an empty part");
    walked = join_path(walked, key);
    if (dot == std::string_view::npos) {
      current[key] = parsed;
      break;
    }
    YAML::Node next = current[key];
    if (!next.IsDefined() || next.IsNull()) {
      current[key] = YAML::Node(YAML::NodeType::Map);
      next.reset(current[key]);
    }
    if (!next.IsMap())
      throw InputError(where, walked + " holds " + found_text(next) + ", not a map of keys");
    current.reset(next);
    rest.remove_prefix(dot + 1);
  }
  source_->overrides[join_path(path_, dotted_path)] = where;
}

YamlNode load_yaml_text(std::string_view text, const std::string& name) {
  auto source = std::make_shared<YamlSource>();
  source->file = name;
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::ParserException& e) {
    throw InputError(location_of(e.mark, name), "this is not valid YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(location_of(e.mark, name), "this is not valid YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    throw InputError(SourceLocation{name, 1, 1}, "the file is empty; expected a YAML map");
  return YamlNode(root, source, "");
}

YamlNode load_yaml_file(const std::string& file, std::size_t max_bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
    throw InputError(SourceLocation{file, 0, 0}, "no such file; check the path");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(SourceLocation{file, 0, 0}, "not a regular file");
  const auto bytes = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(SourceLocation{file, 0, 0}, "cannot read the file's size");
  if (bytes > max_bytes)
    throw InputError(SourceLocation{file, 0, 0},
                     "the file is " + std::to_string(bytes) + " bytes, more than the " +
                         std::to_string(max_bytes) + " bytes a YAML input may have");
  return load_yaml_text(read_text_file(file), file);
}

}  // namespace fl
