// The ranges a scene offers its controls, against the rules' own formulas: the rollers' overlap,
// the plate's length over the amplitude, the LEGO gears' pitch radii, the bench's step count. And
// each edge is an edge: the value there is accepted, one a micrometre beyond is refused by the
// loader, located at the `set` entry that made it, and said in the catalogues (a page's control
// shows it in the page's language).
#include "scene/accepted_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "scene/scene_yaml.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

// A bare rig: no drive, no sensor, the plate released at rest 20 mm off centre.
const std::string kBare = R"(format: 1
world:
  time_step: 1 ms
rollers:
  spacing: 89 mm
  radius: 10 mm
  speed: 1600 rpm
plate:
  length: 200 mm
  thickness: 5 mm
  offset: 20 mm
friction:
  mu_k: 0.3
)";

const AcceptedRange& range_of(const std::vector<AcceptedRange>& ranges, const std::string& key) {
  for (const AcceptedRange& r : ranges)
    if (r.key == key) return r;
  throw std::runtime_error("no range for " + key);
}

Scene bare(std::vector<SceneOverride> overrides = {}) {
  return load_scene_text(kBare, "bare.yaml", overrides,
                         []() -> const PaperTable& { return test::paper_table(); });
}

Scene paper_rig(std::vector<SceneOverride> overrides = {}) {
  return test::scene_file("paper-rig.yaml", overrides);
}

// The key of the problem the loader locates at a `set` entry, or "" when it loads.
std::string refused_entry(const std::function<Scene()>& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.where().field_value.value_or("(in the file)");
  }
  return "";
}

constexpr double kClose =
    1e-8;  // m: an edge not taken is given 1e-8 inside it, far finer than any step

TEST(AcceptedRanges, TheBareRigsSpacingRunsFromTheRollersTouchingToThePlatesLength) {
  const std::vector<AcceptedRange> ranges = accepted_ranges(bare());
  const AcceptedRange& spacing = range_of(ranges, "rollers.spacing");
  EXPECT_EQ(spacing.unit, "m");
  // The rollers overlap at l = 2 a = 20 mm; the plate (200 mm) leaves a roller at l + 2 A = L,
  // A = 20 mm released at rest.
  EXPECT_NEAR(spacing.least, 0.020, kClose);
  EXPECT_GT(spacing.least, 0.020);  // 20 mm itself is refused: the range starts just inside
  EXPECT_NEAR(spacing.most, 0.200 - 2 * 0.020, kClose);
  EXPECT_LT(spacing.most, 0.160);
  // The plate stays on both rollers while |offset| < (L - l) / 2.
  const AcceptedRange& offset = range_of(ranges, "plate.offset");
  EXPECT_NEAR(offset.most, 0.5 * (0.200 - 0.089), kClose);
  EXPECT_NEAR(offset.least, -0.5 * (0.200 - 0.089), kClose);
  // From one step to 1e9 of them.
  const AcceptedRange& duration = range_of(ranges, "world.duration");
  EXPECT_DOUBLE_EQ(duration.least, 1e-3);
  EXPECT_DOUBLE_EQ(duration.most, 1e6);
  // No drive: the rollers' own speed is turned, not a motor's duty.
  EXPECT_EQ(range_of(ranges, "rollers.speed").unit, "rad/s");
  EXPECT_THROW(range_of(ranges, "drive.motor.duty"), std::runtime_error);
}

TEST(AcceptedRanges, ThePaperRigsSpacingIsWhatItsLegoGearsSpan) {
  const std::vector<AcceptedRange> ranges = accepted_ranges(paper_rig());
  const AcceptedRange& spacing = range_of(ranges, "rollers.spacing");
  // LEGO spur gears have a 1 mm module: a pitch radius of half the tooth count in mm. The idlers
  // (40 teeth, 20 mm) meet between the rollers at l = 40 mm; the chain of 24-40-40-24 stretched
  // straight spans 12 + 40 + 40 + 12 = 104 mm.
  // Both bounds are the rules' own and taken: they are given as they are.
  EXPECT_EQ(spacing.least, 0.040);
  EXPECT_EQ(spacing.most, 0.104);
  const AcceptedRange& duty = range_of(ranges, "drive.motor.duty");
  EXPECT_EQ(duty.unit, "");
  EXPECT_LE(duty.most, 1.0);
}

TEST(AcceptedRanges, EachEdgeIsAcceptedAndJustBeyondItTheEntryIsRefused) {
  for (const bool drive : {false, true}) {
    const auto load = [drive](std::vector<SceneOverride> o) {
      return drive ? paper_rig(std::move(o)) : bare(std::move(o));
    };
    for (const AcceptedRange& r : accepted_ranges(load({}))) {
      if (r.key == "world.duration" || r.unit == "rad/s" || r.unit.empty()) continue;
      for (const auto& [edge, beyond] :
           {std::pair{r.least, r.least - 1e-6}, std::pair{r.most, r.most + 1e-6}}) {
        const auto entry = [&](double v) {
          return SceneOverride{r.key, std::to_string(v * 1e3) + " mm"};
        };
        // The edge rounded inward to a micrometre, as a slider's value would be.
        const double inside = edge == r.least ? edge + 1e-6 : edge - 1e-6;
        EXPECT_EQ(refused_entry([&] { return load({entry(inside)}); }), "")
            << r.key << " at " << inside;
        const SceneOverride out = entry(beyond);
        EXPECT_EQ(refused_entry([&] { return load({out}); }), out.path + "=" + out.value)
            << r.key << " at " << beyond << (drive ? " (drive)" : "");
      }
    }
  }
}

// What a value a control offers would be refused with: the loader's Said, or nullopt.
std::optional<Said> refusal_said(const std::function<Scene()>& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.said();
  }
  return std::nullopt;
}

// A value in the range's unit as a `set` entry writes it, with every digit a double needs.
std::string entry_text(double si, const std::string& unit) {
  char digits[64];
  std::snprintf(digits, sizeof digits, "%.17g", unit == "m" ? si * 1e3 : si);
  return std::string(digits) + (unit == "m" ? " mm" : unit.empty() ? "" : " " + unit);
}

TEST(AcceptedRanges, BeyondEachEdgeTheRefusalIsSaidInTheCatalogues) {
  for (const bool drive : {false, true}) {
    const auto load = [drive](std::vector<SceneOverride> o) {
      return drive ? paper_rig(std::move(o)) : bare(std::move(o));
    };
    for (const AcceptedRange& r : accepted_ranges(load({}))) {
      for (const double beyond : {r.least - 1e-6 * std::max(1.0, std::fabs(r.least)),
                                  r.most + 1e-6 * std::max(1.0, std::fabs(r.most))}) {
        const SceneOverride out{r.key, entry_text(beyond, r.unit)};
        const std::optional<Said> said = refusal_said([&] { return load({out}); });
        ASSERT_TRUE(said.has_value()) << r.key << "=" << out.value << (drive ? " (drive)" : "")
                                      << ": refused in English only, or not refused";
        EXPECT_EQ(english(*said).find("{$"), std::string::npos) << english(*said);
        EXPECT_EQ(english(*said).find("lacks"), std::string::npos) << english(*said);
      }
    }
  }
}

}  // namespace
}  // namespace fl
