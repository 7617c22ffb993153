// The sweep file: strict keys with located errors, axes (lists, linear and log ranges, the
// paper's materials and rows, temperatures, seeds), product and zip, shards, and the plan.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/field_spelling.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/sweep/sweep_spec.hpp"

namespace fl {
namespace {

const std::string kSweeps = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/sweeps";

const PaperTable& table() {
  static const PaperTable t = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  return t;
}
const PaperTableSource kPaper = []() -> const PaperTable& { return table(); };
const SceneInputs kInputs{kPaper, {}};

SweepSpec load(const std::string& text) {
  return load_sweep_text(text, "t.yaml", kSweeps, kInputs);
}

const std::string kHead = "format: 1\nscene: ../minimal.yaml\n";

std::string error_of(const std::string& text) {
  try {
    load(text);
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "no error";
}

std::vector<std::string> labels(const SweepSpec& spec, std::size_t index) {
  return sweep_point(spec, index).labels;
}

TEST(SweepSpec, ProductOfAxesLastFastest) {
  const SweepSpec spec = load(kHead +
                              "set:\n  world.duration: 2 s\n"
                              "axes:\n"
                              "  - material: [lego, cardboard]\n"
                              "  - key: rollers.spacing\n"
                              "    values: [60 mm, 80 mm, 100 mm]\n");
  ASSERT_EQ(spec.point_count(), 6u);
  EXPECT_EQ(spec.name, "t");
  EXPECT_EQ(labels(spec, 0), (std::vector<std::string>{"lego", "60 mm"}));
  EXPECT_EQ(labels(spec, 1), (std::vector<std::string>{"lego", "80 mm"}));
  EXPECT_EQ(labels(spec, 3), (std::vector<std::string>{"cardboard", "60 mm"}));
  EXPECT_EQ(labels(spec, 5), (std::vector<std::string>{"cardboard", "100 mm"}));
  // `set:` first, then each axis's keys in order.
  const SweepPoint p = sweep_point(spec, 4);
  ASSERT_EQ(p.overrides.size(), 4u);
  EXPECT_EQ(p.overrides[0].path, "world.duration");
  EXPECT_EQ(p.overrides[1].path, "friction.mu_k");
  EXPECT_EQ(p.overrides[1].value, "cardboard");
  EXPECT_EQ(p.overrides[2].path, "plate.material");
  EXPECT_EQ(p.overrides[3].path, "rollers.spacing");
  EXPECT_EQ(p.overrides[3].value, "80 mm");
  const auto axes = spec.axes();
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[0]->name, "material");
  EXPECT_EQ(axes[1]->name, "rollers.spacing");
  EXPECT_EQ(axes[1]->unit, "mm");
  EXPECT_DOUBLE_EQ(*axes[1]->values[2].number, 100.0);
  EXPECT_EQ(expand_sweep(spec).size(), 6u);
}

TEST(SweepSpec, ZippedAxesGoTogether) {
  const SweepSpec spec = load(kHead +
                              "axes:\n"
                              "  - zip:\n"
                              "      - {key: rollers.spacing, values: [60 mm, 80 mm]}\n"
                              "      - {key: plate.offset, values: [10 mm, 15 mm], name: A}\n"
                              "  - seeds: 2\n");
  ASSERT_EQ(spec.point_count(), 4u);
  EXPECT_EQ(labels(spec, 0), (std::vector<std::string>{"60 mm", "10 mm", "1"}));
  EXPECT_EQ(labels(spec, 1), (std::vector<std::string>{"60 mm", "10 mm", "2"}));
  EXPECT_EQ(labels(spec, 2), (std::vector<std::string>{"80 mm", "15 mm", "1"}));
  EXPECT_EQ(spec.axes()[1]->name, "A");
  EXPECT_EQ(sweep_point(spec, 3).overrides.back().path, "world.seed");
  EXPECT_EQ(sweep_point(spec, 3).overrides.back().value, "2");
}

TEST(SweepSpec, LinearAndLogRanges) {
  const SweepSpec spec = load(kHead +
                              "axes:\n"
                              "  - {key: rollers.spacing, from: 40 mm, to: 200 mm, steps: 5}\n"
                              "  - {key: rollers.speed, from: 50 rpm, to: 2000 rpm, steps: 3, "
                              "scale: log}\n");
  const auto axes = spec.axes();
  std::vector<std::string> spacing, speed;
  for (const SweepValue& v : axes[0]->values) spacing.push_back(v.label);
  for (const SweepValue& v : axes[1]->values) speed.push_back(v.label);
  EXPECT_EQ(spacing, (std::vector<std::string>{"40 mm", "80 mm", "120 mm", "160 mm", "200 mm"}));
  EXPECT_EQ(speed, (std::vector<std::string>{"50 rpm", "316.227766017 rpm", "2000 rpm"}));
  EXPECT_TRUE(axes[1]->log_scale);
  EXPECT_EQ(axes[1]->unit, "rpm");
  // Log steps have a constant ratio.
  EXPECT_NEAR(*axes[1]->values[1].number / 50.0, 2000.0 / *axes[1]->values[1].number, 1e-9);
  EXPECT_EQ(spec.point_count(), 15u);
}

TEST(SweepSpec, PaperRowsTemperaturesAndMaterials) {
  const SweepSpec all = load(kHead + "axes:\n  - paper_rows: all\n");
  ASSERT_EQ(all.point_count(), 15u);  // ten materials at 300 K, five at 77 K
  EXPECT_EQ(labels(all, 0), (std::vector<std::string>{"lego 300 K"}));
  EXPECT_EQ(labels(all, 10), (std::vector<std::string>{"lego 77 K"}));
  const SweepPoint cold = sweep_point(all, 14);
  EXPECT_EQ(cold.labels[0], "flexible-foam 77 K");
  EXPECT_EQ(cold.overrides.back().path, "friction.temperature");
  EXPECT_EQ(cold.overrides.back().value, "77 K");

  EXPECT_EQ(load(kHead + "axes:\n  - paper_rows: [77 K]\n").point_count(), 5u);
  EXPECT_EQ(load(kHead + "axes:\n  - material: all\n").point_count(), 10u);
  const SweepSpec t = load(kHead + "axes:\n  - temperature: [300 K, 77 K]\n");
  EXPECT_EQ(labels(t, 1), (std::vector<std::string>{"77 K"}));
  EXPECT_EQ(sweep_point(t, 1).overrides[0].path, "friction.temperature");
  const SweepSpec seeds = load(kHead + "axes:\n  - seeds: [3, 9]\n");
  EXPECT_EQ(labels(seeds, 1), (std::vector<std::string>{"9"}));
}

TEST(SweepSpec, NonScalarValuesAreOverridesInFlowStyle) {
  const SweepSpec spec = load(kHead +
                              "set:\n  sensor.position: [100 mm, 0 mm, 15 mm]\n"
                              "axes:\n"
                              "  - key: magnets\n"
                              "    values: [[{x: 95 mm}], [{x: -95 mm}, {x: 95 mm}]]\n");
  EXPECT_EQ(spec.set[0].value, "[100 mm, 0 mm, 15 mm]");
  EXPECT_EQ(sweep_point(spec, 0).overrides[1].value, "[{x: 95 mm}]");
  EXPECT_FALSE(spec.axes()[0]->values[0].number);
}

TEST(SweepSpec, ErrorsAreLocated) {
  struct Case {
    std::string text;
    std::string message;
  };
  for (const Case& c : {
           Case{kHead + "axs: []\n", "t.yaml:3:1: error: axs: unknown key; did you mean 'axes'?"},
           Case{"format: 2\nscene: ../minimal.yaml\naxes: [{seeds: 2}]\n",
                "t.yaml:1:9: error: format: this build reads sweep format 1, found 2"},
           Case{kHead + "axes:\n  - {key: rollers.spacing, value: [1 mm]}\n",
                "t.yaml:4:28: error: axes[0].value: unknown key; did you mean 'values'?"},
           Case{kHead + "axes:\n  - {key: rollers.spacing, values: [60 mm], from: 1 mm}\n",
                "t.yaml:4:36: error: axes[0].values: give either values or a range (from, to, "
                "steps), not both"},
           Case{kHead + "axes:\n  - {key: rollers.spacing, from: 60 mm, to: 0.12, steps: 2}\n",
                "t.yaml:4:45: error: axes[0].to: expected a number with the unit of from (\"mm\"), "
                "found \"0.12\" with none: a plain number is SI"},
           Case{kHead + "axes:\n  - {key: rollers.spacing, from: 40 mm, to: 20 cm, steps: 3}\n",
                "t.yaml:4:45: error: axes[0].to: from and to must be in the same unit (found "
                "\"mm\" and \"cm\")"},
           Case{kHead + "axes:\n  - {key: rollers.speed, from: 0 rpm, to: 20 rpm, steps: 3, "
                        "scale: log}\n",
                "t.yaml:4:68: error: axes[0].scale: a log range needs from and to above zero"},
           Case{kHead + "axes:\n  - {key: rollers.speed, from: 1 rpm, to: 20 rpm, steps: 0}\n",
                "t.yaml:4:58: error: axes[0].steps: expected a whole number of values from 1 to "
                "1000000"},
           Case{kHead + "axes:\n  - material: [lego, unobtainium]\n",
                "t.yaml:4:22: error: axes[0].material[1]: \"unobtainium\" is not a material of "
                "the paper's Table I"},
           Case{kHead + "axes:\n  - {material: [lego], seeds: 2}\n",
                "t.yaml:4:31: error: axes[0].seeds: an axis sweeps one thing; found both material "
                "and seeds (use zip: to pair axes)"},
           Case{kHead + "axes:\n  - zip:\n      - {seeds: 2}\n      - {seeds: [5, 6]}\n",
                "t.yaml:6:9: error: two axes are named \"seed\"; give one a name: for its column"},
           Case{kHead + "axes:\n  - zip:\n      - {key: plate.offset, values: [1 mm, 2 mm]}\n"
                        "      - {seeds: 3}\n",
                "t.yaml:5:7: error: axes[0].zip: zipped axes need as many values each: "
                "plate.offset has 2, seed has 3"},
           Case{kHead + "axes:\n  - {material: [lego]}\n  - {key: friction.mu_k, values: [0.3]}\n",
                "t.yaml:5:5: error: two axes set friction.mu_k; sweep it once"},
           Case{kHead + "axes:\n  - {key: rollers.spacing, from: 1 mm, to: 2 mm, steps: 1001}\n"
                        "  - {key: plate.offset, from: 1 mm, to: 2 mm, steps: 1001}\n",
                "t.yaml:4:3: error: axes: the axes make 1002001 points; a sweep holds at most "
                "1000000"},
           Case{"format: 1\nscene: nowhere.yaml\naxes: [{seeds: 2}]\n",
                "t.yaml:2:8: error: scene: no scene file at"},
           Case{kHead + "axes: []\n", "t.yaml:3:7: error: axes: expected at least one axis"},
           Case{kHead + "accuracy: 0 %\naxes: [{seeds: 2}]\n",
                "t.yaml:3:11: error: accuracy: expected a period accuracy above 0 and at most "
                "10 % (e.g. 0.01%), found 0"},
           Case{kHead + "accuracy: 2 mm\naxes: [{seeds: 2}]\n", "t.yaml:3:11: error: accuracy:"},
           Case{kHead + "accuracy: 0.01%\nset: {world.time_step: 2 ms}\naxes: [{seeds: 2}]\n",
                "t.yaml:3:11: error: accuracy: the accuracy picks each point's time step, and the "
                "sweep sets world.time_step as well; drop one of them"},
           Case{kHead + "accuracy: 0.01%\naxes: [{key: world.time_step, values: [1 ms]}]\n",
                "t.yaml:3:11: error: accuracy: the accuracy picks each point's time step"},
           Case{kHead + "period: hal\naxes: [{seeds: 2}]\n",
                "t.yaml:3:9: error: period: expected hall (the rig's estimator on the simulated "
                "Hall signal, and the trajectory's period) or trajectory"},
       }) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.substr(0, c.message.size()), c.message) << c.text;
  }
}

TEST(SweepSpec, AKeyPathTheSceneDoesNotHaveIsLocatedInTheSweepFile) {
  const std::string message =
      error_of(kHead + "axes:\n  - key: rollers.spaceing\n    values: [60 mm]\n");
  EXPECT_EQ(message.substr(0, 80),
            "t.yaml:4:5: error: axis rollers.spaceing: \"rollers.spaceing\" is not a key of the");
  EXPECT_NE(message.find("did you mean 'spacing'?"), std::string::npos) << message;
  const std::string top = error_of(kHead + "set:\n  roller.spacing: 60 mm\naxes: [{seeds: 2}]\n");
  EXPECT_EQ(top.substr(0, 56), "t.yaml:4:19: error: set: \"roller.spacing\" is not a key o") << top;
  // A bad value is not the file's error: that point will report it.
  EXPECT_EQ(load(kHead + "axes:\n  - {key: rollers.spacing, values: [-5 mm, abc]}\n").point_count(),
            2u);
}

TEST(SweepSpec, SweepFilesInTheRepositoryLoad) {
  for (const char* name :
       {"materials.yaml", "spacing.yaml", "roller-speed.yaml", "roller-speed-ramp.yaml",
        "runout.yaml", "materials-spacings.yaml", "skew.yaml", "tilt.yaml",
        "rolling-resistance.yaml", "hall-accuracy.yaml"}) {
    const SweepSpec spec = load_sweep_file(kSweeps + "/" + name, kInputs);
    EXPECT_GT(spec.point_count(), 1u) << name;
  }
  EXPECT_EQ(load_sweep_file(kSweeps + "/spacing.yaml", kInputs).point_count(), 120u);
  EXPECT_EQ(load_sweep_file(kSweeps + "/materials.yaml", kInputs).point_count(), 15u);
  EXPECT_EQ(load_sweep_file(kSweeps + "/roller-speed.yaml", kInputs).point_count(), 40u);
  const SweepSpec fast = load_sweep_file(kSweeps + "/materials-spacings.yaml", kInputs);
  EXPECT_EQ(fast.point_count(), 10008u);
  ASSERT_TRUE(fast.accuracy.has_value());
  EXPECT_DOUBLE_EQ(*fast.accuracy, 1e-4);
  EXPECT_FALSE(fast.hall);
}

// The accuracy and the period's source change every point's result, so they are part of the plan
// (a folder run at one accuracy is not resumed at another); a plan without them keeps its bytes.
TEST(SweepSpec, TheAccuracyAndThePeriodsSourceArePartOfThePlan) {
  const SweepSpec plain = load(kHead + "axes: [{seeds: 2}]\n");
  EXPECT_FALSE(sweep_plan(plain).contains("accuracy"));
  EXPECT_FALSE(sweep_plan(plain).contains("period"));
  SweepSpec fine = load(kHead + "accuracy: 0.01%\nperiod: trajectory\naxes: [{seeds: 2}]\n");
  EXPECT_DOUBLE_EQ(sweep_plan(fine)["accuracy"].get<double>(), 1e-4);
  EXPECT_EQ(sweep_plan(fine)["period"], "trajectory");
  // The command line's --accuracy replaces the file's.
  set_sweep_accuracy(fine, 1e-3, SourceLocation::of_field("accuracy", "0.1%"));
  EXPECT_DOUBLE_EQ(sweep_plan(fine)["accuracy"].get<double>(), 1e-3);
  EXPECT_NE(sweep_plan(fine), sweep_plan(load(kHead + "accuracy: 0.01%\naxes: [{seeds: 2}]\n")));
}

TEST(SweepSpec, RollerSpeedRampSweepRunsOneRampPerLawAndRecordsCycles) {
  const SweepSpec spec = load_sweep_file(kSweeps + "/roller-speed-ramp.yaml", kInputs);
  EXPECT_EQ(spec.point_count(), 4u);
  EXPECT_TRUE(spec.cycles);
  EXPECT_EQ(sweep_plan(spec).value("cycles", false), true);
  // Each point is the ramp's scene with one law, and the scene loads with it.
  const std::vector<std::pair<FrictionLawKind, double>> laws{{FrictionLawKind::kCoulomb, 0.29},
                                                             {FrictionLawKind::kCoulomb, 0.348},
                                                             {FrictionLawKind::kStribeck, 0.348},
                                                             {FrictionLawKind::kStribeck, 0.29}};
  for (std::size_t i = 0; i < spec.point_count(); ++i) {
    const SweepPoint point = sweep_point(spec, i);
    const Scene scene =
        load_scene_text(spec.scene_text, spec.scene_file, point.overrides, kInputs.paper);
    const FrictionLaw law = friction_law(scene.friction);
    EXPECT_EQ(law.kind, laws[i].first) << i;
    EXPECT_DOUBLE_EQ(law.mu_k, 0.29) << i;
    EXPECT_DOUBLE_EQ(law.mu_s, laws[i].second) << i;
    ASSERT_FALSE(scene.rollers.speed_ramp.empty()) << i;
  }
  EXPECT_DOUBLE_EQ(friction_law(load_scene_text(spec.scene_text, spec.scene_file,
                                                sweep_point(spec, 2).overrides, kInputs.paper)
                                    .friction)
                       .v_s,
                   0.005);
  EXPECT_DOUBLE_EQ(load_scene_text(spec.scene_text, spec.scene_file, sweep_point(spec, 3).overrides,
                                   kInputs.paper)
                       .friction.beta,
                   -0.0002);
  // Without `cycles:` a plan says nothing of them (its bytes are as before).
  EXPECT_FALSE(sweep_plan(load(kHead + "axes:\n  - {key: rollers.spacing, values: [60 mm]}\n"))
                   .contains("cycles"));
}

TEST(SweepSpec, PlanNamesEveryPointAndChangesWithIt) {
  const std::string text = kHead + "axes:\n  - {key: rollers.spacing, values: [60 mm, 80 mm]}\n";
  const nlohmann::json a = sweep_plan(load(text));
  EXPECT_EQ(a, sweep_plan(load(text)));
  EXPECT_EQ(a["points"].size(), 2u);
  EXPECT_EQ(a["points"][1][0], "rollers.spacing=80 mm");
  EXPECT_EQ(a["scene"], "minimal");
  std::string other = text;
  other.replace(other.find("80 mm"), 5, "81 mm");
  EXPECT_NE(text_digest(a.dump()), text_digest(sweep_plan(load(other)).dump()));
  EXPECT_EQ(text_digest(""), "cbf29ce484222325");
}

TEST(SweepSpec, Shards) {
  const Shard s = parse_shard("2/3");
  EXPECT_EQ(s.k, 2u);
  EXPECT_EQ(s.n, 3u);
  EXPECT_FALSE(s.contains(0));
  EXPECT_TRUE(s.contains(1));
  EXPECT_TRUE(s.contains(4));
  for (const char* bad : {"0/3", "4/3", "x", "2-3", "2/", "/3", "1/0", "-1/3"})
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
  try {
    parse_shard("4/3");
  } catch (const InputError& e) {
    EXPECT_EQ(cli::spelled(e.what()),
              "--shard 4/3: error: K must be from 1 to N (shard K of N), found 4/3");
  }
}

TEST(SweepSpec, AnUnknownMaterialIsAnsweredWithTheTablesMaterials) {
  const std::string message = error_of(kHead + "axes:\n  - material: [lego, cardbord]\n");
  EXPECT_NE(message.find("\"cardbord\" is not a material of the paper's Table I; the paper's "
                         "materials are lego, paper, "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("did you mean 'cardboard'?"), std::string::npos) << message;
}

}  // namespace
}  // namespace fl
