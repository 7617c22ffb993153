// Strict, located YAML reading: errors name file:line:column (1-based), the key path, what was
// expected and what was found; unknown keys suggest the closest known one.
#include "io/yaml_node.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/suggest.hpp"

namespace fl {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlNode, UnknownKeyIsLocatedAndSuggestsTheClosest) {
  const YamlNode root = load_yaml_text("rollers:\n  spacng: 89 mm\n  radius: 10 mm\n", "s.yaml");
  const YamlNode rollers = root.at("rollers");
  const std::string message = error_of([&] { rollers.allow_keys({"spacing", "radius", "speed"}); });
  EXPECT_EQ(message, "s.yaml:2:3: error: rollers.spacng: unknown key; did you mean 'spacing'?");
}

TEST(YamlNode, UnknownKeyFarFromAnyListsTheKeys) {
  const YamlNode root = load_yaml_text("zzzzzz: 1\n", "s.yaml");
  EXPECT_EQ(error_of([&] {
              root.allow_keys({"world", "plate"});
            }),
            "s.yaml:1:1: error: zzzzzz: unknown key; the keys here are: world plate");
}

TEST(YamlNode, WrongUnitIsLocatedAtTheValue) {
  const YamlNode root = load_yaml_text("plate:\n  thickness: 5 kg\n", "s.yaml");
  const std::string message =
      error_of([&] { root.at("plate").at("thickness").quantity(Dimension::kLength); });
  EXPECT_NE(message.find("s.yaml:2:14: error: plate.thickness: expected a length"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("found \"5 kg\""), std::string::npos) << message;
}

TEST(YamlNode, MissingKeyAndWrongKinds) {
  const YamlNode root = load_yaml_text("plate:\n  length: [1, 2]\n", "s.yaml");
  EXPECT_EQ(error_of([&] { root.at("plate").at("width"); }),
            "s.yaml:2:3: error: plate: the key 'width' is required but missing");
  EXPECT_NE(error_of([&] {
              root.at("plate").at("length").quantity(Dimension::kLength);
            }).find("expected a length, found a list"),
            std::string::npos);
  EXPECT_NE(error_of([&] { root.at("plate").at("length")[0].boolean(); }).find("true or false"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              load_yaml_text("n: 1.5\n", "s.yaml").at("n").integer();
            }).find("whole number"),
            std::string::npos);
}

TEST(YamlNode, DuplicateKeysAreRefused) {
  const YamlNode root = load_yaml_text("a: 1\nb: 2\na: 3\n", "s.yaml");
  EXPECT_EQ(error_of([&] {
              root.allow_keys({"a", "b"});
            }),
            "s.yaml:3:1: error: a: the key is given twice; keep one");
}

TEST(YamlNode, NotYamlEmptyMissingAndHugeFilesAreRefused) {
  EXPECT_NE(error_of([] { load_yaml_text("a: [1, 2\n", "bad.yaml"); }).find("bad.yaml:"),
            std::string::npos);
  EXPECT_NE(error_of([] { load_yaml_text("a: [1, 2\n", "bad.yaml"); }).find("not valid YAML"),
            std::string::npos);
  EXPECT_EQ(error_of([] { load_yaml_text("", "empty.yaml"); }),
            "empty.yaml:1:1: error: the file is empty; expected a YAML map");
  EXPECT_EQ(error_of([] { load_yaml_file("/nonexistent/x.yaml"); }),
            "/nonexistent/x.yaml: error: no such file; check the path");
  const std::string big = std::string(FRICTIONLAB_TEST_BINARY_DIR) + "/big-test.yaml";
  {
    std::ofstream out(big);
    out << "a: " << std::string(2000, 'x') << "\n";
  }
  EXPECT_NE(error_of([&] { load_yaml_file(big, 1000); }).find("more than the 1000 bytes"),
            std::string::npos);
  std::filesystem::remove(big);
}

TEST(Suggest, EditDistanceAndClosestMatch) {
  EXPECT_EQ(edit_distance("spacing", "spacing"), 0);
  EXPECT_EQ(edit_distance("spacng", "spacing"), 1);
  EXPECT_EQ(edit_distance("sapcing", "spacing"), 1);  // a swap counts once
  EXPECT_EQ(edit_distance("", "abc"), 3);
  const std::string_view keys[] = {"spacing", "radius", "speed"};
  EXPECT_EQ(closest_match("Spacing", keys), "spacing");
  EXPECT_EQ(closest_match("sped", keys), "speed");
  EXPECT_EQ(closest_match("thickness", keys), "");
}

}  // namespace
}  // namespace fl
