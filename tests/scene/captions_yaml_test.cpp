// A video's captions, as a scene's `video.captions` and as a captions file (run --captions): times
// with units, `until` optional, UTF-8 text; out-of-order, overlapping or negative times, empty
// text and unknown keys are refused, each located at its key.
#include "scene/captions_yaml.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "io/yaml_node.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {
namespace {

std::vector<Caption> read(const std::string& list) {
  return read_captions(load_yaml_text(list, "c.yaml"));
}

std::string error_of(const std::string& list) {
  try {
    read(list);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A scene whose `video` part holds the captions (mu_k given: no paper table is read).
Scene scene_with(const std::string& video) {
  const std::string text =
      "format: 1\n"
      "rollers: {spacing: 89 mm, radius: 10 mm}\n"
      "plate: {length: 200 mm, thickness: 5 mm, offset: 20 mm}\n"
      "friction: {mu_k: 0.3}\n"
      "video:\n" +
      video;
  return load_scene_text(text, "v.yaml", {}, []() -> const PaperTable& {
    throw std::logic_error("the scene names no paper material");
  });
}

TEST(Captions, AreReadWithTheirTimesAndText) {
  const std::vector<Caption> c = read(
      "- {at: 0 s, text: \"The rollers turn toward each other.\"}\n"
      "- {at: 1500 ms, until: 4 s, text: \"\xce\xbc\xe2\x82\x96 = "
      "2\xcf\x80\xc2\xb2l/(gT\xc2\xb2)\"}\n"
      "- at: 6 s\n"
      "  text: |\n"
      "    Two lines,\n"
      "    as written.\n");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c[0].at, 0.0);
  EXPECT_FALSE(c[0].until.has_value());
  EXPECT_EQ(c[0].text, "The rollers turn toward each other.");
  EXPECT_DOUBLE_EQ(c[1].at, 1.5);
  ASSERT_TRUE(c[1].until.has_value());
  EXPECT_DOUBLE_EQ(*c[1].until, 4.0);
  EXPECT_EQ(c[1].text, "\xce\xbc\xe2\x82\x96 = 2\xcf\x80\xc2\xb2l/(gT\xc2\xb2)");
  EXPECT_DOUBLE_EQ(c[2].at, 6.0);
  EXPECT_EQ(c[2].text, "Two lines,\nas written.");  // the block's final line end trimmed
  EXPECT_TRUE(read("[]\n").empty());
}

TEST(Captions, OutOfOrderOrOverlappingTimesAreRefusedAtTheirKey) {
  const std::string earlier = error_of(
      "- {at: 3 s, text: a}\n"
      "- {at: 2 s, text: b}\n");
  EXPECT_NE(earlier.find("c.yaml:2:8: error: [1].at: expected a time after the previous "
                         "caption's (3 s), found 2 s"),
            std::string::npos)
      << earlier;
  EXPECT_NE(error_of("- {at: 3 s, text: a}\n- {at: 3 s, text: b}\n").find("after the previous"),
            std::string::npos);
  const std::string overlap = error_of(
      "- {at: 1 s, until: 5 s, text: a}\n"
      "- {at: 4 s, text: b}\n");
  EXPECT_NE(overlap.find("c.yaml:2:8: error: [1].at: the previous caption shows until 5 s"),
            std::string::npos)
      << overlap;
  const std::string backwards = error_of("- {at: 2 s, until: 1 s, text: a}\n");
  EXPECT_NE(backwards.find("c.yaml:1:20: error: [0].until: expected a time after the caption's "
                           "`at` (2 s)"),
            std::string::npos)
      << backwards;
  // Ending exactly where the next begins is no overlap.
  EXPECT_EQ(read("- {at: 1 s, until: 4 s, text: a}\n- {at: 4 s, text: b}\n").size(), 2u);
}

// A caption names the run's values by the placeholders the video fills in; any other {name} is
// a typo, refused at its text.
TEST(Captions, OnlyTheRunsPlaceholdersAreTaken) {
  EXPECT_EQ(error_of("- {at: 0 s, text: \"{material}: mu_k {mu_k}, T {T}, {temperature}, "
                     "{spacing}\"}\n"),
            "");
  const std::string typo = error_of("- {at: 0 s, text: \"mu_k {muk}\"}\n");
  EXPECT_NE(typo.find("[0].text: unknown placeholder \"{muk}\": a caption may name the run's "
                      "{mu_k}"),
            std::string::npos)
      << typo;
  EXPECT_NE(error_of("- {at: 0 s, text: \"a { b\"}\n").find("unknown placeholder \"{ b\""),
            std::string::npos);
}

TEST(Captions, NegativeTimesMissingUnitsAndEmptyTextAreRefused) {
  const std::string negative = error_of("- {at: -1 s, text: a}\n");
  EXPECT_NE(negative.find("c.yaml:1:8: error: [0].at: expected a simulated time of 0 s or later"),
            std::string::npos)
      << negative;
  EXPECT_NE(error_of("- {at: 2 m, text: a}\n").find("[0].at: expected a time"), std::string::npos)
      << error_of("- {at: 2 m, text: a}\n");
  const std::string empty = error_of("- {at: 0 s, text: \"  \"}\n");
  EXPECT_NE(empty.find("c.yaml:1:19: error: [0].text: expected the caption's text, found none"),
            std::string::npos)
      << empty;
  EXPECT_NE(error_of("- {at: 0 s}\n").find("the key 'text' is required"), std::string::npos);
  EXPECT_NE(error_of("- {text: a}\n").find("the key 'at' is required"), std::string::npos);
  EXPECT_NE(error_of("- {at: 0 s, text: \"caf\xe9\"}\n").find("expected UTF-8 text"),
            std::string::npos)
      << error_of("- {at: 0 s, text: \"caf\xe9\"}\n");
  const std::string too_long = error_of("- {at: 0 s, text: \"" + std::string(201, 'a') + "\"}\n");
  EXPECT_NE(too_long.find("at most 200 characters"), std::string::npos) << too_long;
  // 200 characters of two bytes each are 200 characters.
  std::string greek;
  for (int i = 0; i < 200; ++i) greek += "\xce\xbc";
  EXPECT_EQ(read("- {at: 0 s, text: \"" + greek + "\"}\n").size(), 1u);
}

TEST(Captions, InTheSceneUnknownKeysAreLocatedWithASuggestion) {
  const Scene s = scene_with(
      "  captions:\n"
      "    - {at: 0 s, text: first}\n"
      "    - {at: 2 s, until: 3 s, text: second}\n");
  ASSERT_TRUE(s.video.has_value());
  ASSERT_EQ(s.video->captions.size(), 2u);
  EXPECT_EQ(s.video->captions[1].text, "second");
  try {
    scene_with("  captions:\n    - {at: 0 s, txt: first}\n");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "v.yaml:7:17: error: video.captions[0].txt: unknown key; did you mean 'text'?");
  }
  try {
    scene_with("  caption:\n    - {at: 0 s, text: first}\n");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("v.yaml:6:3: error: video.caption: unknown key; did you "
                                         "mean 'captions'?"),
              std::string::npos)
        << e.what();
  }
}

TEST(Captions, AFileHoldsTheListUnderCaptions) {
  const auto dir = std::filesystem::path(FRICTIONLAB_TEST_BINARY_DIR) / "captions-yaml-test";
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string good = write("good.yaml", "captions:\n  - {at: 1 s, text: hello}\n");
  const std::vector<Caption> c = load_captions_file(good);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].text, "hello");
  const auto message = [](const std::string& file) -> std::string {
    try {
      load_captions_file(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string bad = write("bad.yaml", "captions:\n  - {at: 1 s, text: a}\n  - {at: 2 s}\n");
  EXPECT_NE(message(bad).find(bad + ":3:5: error: captions[1]: the key 'text' is required"),
            std::string::npos)
      << message(bad);
  const std::string list = write("list.yaml", "- {at: 1 s, text: a}\n");
  EXPECT_NE(message(list).find(list + ":1:1: error: expected a map of keys"), std::string::npos)
      << message(list);
  EXPECT_NE(message((dir / "none.yaml").string()).find("no such file"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// The example the docs run (examples/lesson-captions.yaml) reads, in order, within the paper
// rig's 10 s.
TEST(Captions, TheShippedExampleReads) {
  const std::vector<Caption> c = load_captions_file(std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                                                    "/examples/lesson-captions.yaml");
  ASSERT_GE(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c.front().at, 0.0);
  ASSERT_TRUE(c.back().until.has_value());
  EXPECT_LE(*c.back().until, 10.0);
}

}  // namespace
}  // namespace fl
