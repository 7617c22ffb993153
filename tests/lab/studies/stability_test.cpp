// The stability catalogue (scenes/extreme/): every case ends in the regime theory expects, none
// in NaN, a hang or a crash; the stiff cases stay accurate, not merely finite.
#include "lab/studies/stability_study.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/paper_table_yaml.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/regime_theory.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {
namespace {

const std::filesystem::path kCatalogue =
    std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / "scenes" / "extreme";

Scene load_case(const std::string& name) {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  static const assets::PartCatalog parts =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return load_scene_file((kCatalogue / (name + ".yaml")).string(), {},
                         []() -> const PaperTable& { return table; },
                         []() -> const assets::PartCatalog& { return parts; });
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kCatalogue))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Catalogue : public ::testing::TestWithParam<std::string> {};

TEST_P(Catalogue, EndsInTheRegimeTheoryExpects) {
  const Scene scene = load_case(GetParam());
  ASSERT_TRUE(scene.expected_regime.has_value()) << "every case declares expect.regime";
  // The declared regime is theory's (the conditions in docs/physics.md), not a record of a past
  // run.
  EXPECT_EQ(*scene.expected_regime, regime_from_theory(compile_rig(scene)).regime);
  const StabilityRow row = run_stability_case(scene);
  EXPECT_EQ(row.found, row.expected) << row.evidence;
  EXPECT_NE(row.found, Regime::kNumericallyFailed);
  EXPECT_TRUE(row.largest_step.has_value()) << row.step_note;
}

INSTANTIATE_TEST_SUITE_P(Extreme, Catalogue, ::testing::ValuesIn(case_names()),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// mu_k = 10 with h_c = 2.5 mm at l = 89 mm (T near 0.09 s) within 0.1 % of the thick formula at
// the step the stability run finds and reports.
TEST(StiffCases, MuTenWithinOneTenthPercentAtTheReportedStep) {
  Scene scene = load_case("mu-10");
  const StabilityRow row = run_stability_case(scene);
  ASSERT_TRUE(row.largest_step.has_value());
  scene.world.time_step = *row.largest_step;
  const RunSummary r = run_experiment(scene, {});
  ASSERT_EQ(r.regime, Regime::kOscillates);
  ASSERT_TRUE(r.period_thick.has_value());
  EXPECT_NEAR(*r.period_thick, 0.0886, 0.001);
  EXPECT_LE(std::fabs(*r.period_trajectory / *r.period_thick - 1.0), 1e-3);
}

// A 1 g and a 10 kg plate on the same rollers: the same period to rounding (1e-12; 3e-16
// measured). The ideal drive's rollers are kinematic and the friction is proportional to the
// normal force, so the mass drops out of the equation of motion.
TEST(StiffCases, OneGramAndTenKilogramPlatesHaveTheSamePeriod) {
  const RunSummary light = run_experiment(load_case("plate-1g"), {});
  const RunSummary heavy = run_experiment(load_case("plate-10kg"), {});
  ASSERT_TRUE(light.period_trajectory && heavy.period_trajectory);
  EXPECT_NEAR(*light.period_trajectory / *heavy.period_trajectory - 1.0, 0.0, 1e-12);
}

}  // namespace
}  // namespace fl

namespace fl {
namespace {

// The Stribeck drop (v_s = 1 mm/s) is crossed at each breakaway; at 1 ms one step changes the slip
// speed by mu_s g dt = 3.4 mm/s: the run is diagnosed numerical and names the step that resolves
// it, v_s / (mu_s g) = 0.29 ms, at which the same scene runs its stick-slip cycle.
TEST(StiffCases, AStribeckDropNarrowerThanAStepIsDiagnosedNumerical) {
  Scene scene = load_case("stribeck-drop");
  scene.world.time_step = 1e-3;
  const RunSummary coarse = run_experiment(scene, {});
  EXPECT_EQ(coarse.regime, Regime::kNumericallyFailed) << coarse.regime_evidence;
  EXPECT_NE(coarse.regime_evidence.find("world.time_step to 0.293 ms"), std::string::npos)
      << coarse.regime_evidence;
  EXPECT_FALSE(coarse.period.has_value());
  scene.world.time_step = 0.25e-3;
  const RunSummary fine = run_experiment(scene, {});
  EXPECT_EQ(fine.regime, Regime::kStickSlip) << fine.regime_evidence;
}

// The same law at 1600 rpm: the slip margin is about 7, the plate never sticks and so never
// enters the drop, and the run slips throughout at any step (0.25 to 4 ms): it oscillates at the
// thick formula's period less the integrator's bias -(omega dt)^2 / 24 (4.3e-5 at 4 ms), to 5 %
// of the bias plus 1e-5.
TEST(StiffCases, AStribeckDropThePlateNeverReachesNeedsNoSmallStep) {
  for (const double dt : {0.25e-3, 1e-3, 4e-3}) {
    Scene scene = load_case("stribeck-drop");
    scene.rollers.speed = 1600.0 * 2.0 * std::numbers::pi / 60.0;
    scene.world.time_step = dt;
    const RunSummary r = run_experiment(scene, {});
    EXPECT_EQ(r.regime, Regime::kOscillates) << dt << ": " << r.regime_evidence;
    EXPECT_GT(r.slip_margin, 6.0) << dt;
    ASSERT_TRUE(r.period_trajectory && r.period_thick && r.predicted_integrator_bias) << dt;
    const double bias = *r.predicted_integrator_bias;
    EXPECT_NEAR(*r.period_trajectory / *r.period_thick - 1.0, bias, 1e-5 + 0.05 * std::fabs(bias))
        << dt;
  }
}

// A steep falling law (beta = -1 s/m, gamma = 5 /s at 100 rpm) at a step where the amplitude
// e-folds by more than 1 % per step is numerical too.
TEST(StiffCases, AGrowthFasterThanOnePercentPerStepIsDiagnosedNumerical) {
  Scene scene = load_case("beta-steep");
  scene.world.time_step = 4e-3;
  const RunSummary r = run_experiment(scene, {});
  EXPECT_EQ(r.regime, Regime::kNumericallyFailed) << r.regime_evidence;
  EXPECT_NE(r.regime_evidence.find("set world.time_step to"), std::string::npos);
}

}  // namespace
}  // namespace fl
