// Axes not quite parallel (rollers.skew): roller 0's axis turned by +skew/2 about +z, roller 1's by
// -skew/2. Both inward surfaces then move along +y at v_r sin(skew/2) as well as along x. The
// plate's friction from each roller follows its slip, so its slip along y dies out and it drifts
// sideways with the surfaces, v_y = v_r sin(skew/2), whatever the two normal forces; once it
// does, each slip is along x alone and the oscillation is the parallel rig's (docs/physics.md).
// Checked against those two statements, written out here: the drift speed and the period.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

RunSummary run_skewed(const std::string& skew, const std::string& duration) {
  const std::vector<SceneOverride> keys{{"rollers.skew", skew}, {"world.duration", duration}};
  return run_experiment(compile_rig(test::minimal_without_sensor(keys)), {});
}

TEST(SkewedRollers, ThePlateDriftsWithTheSurfacesAndOscillatesAsOnParallelRollers) {
  const Scene level = test::minimal_without_sensor();
  const double v_r = level.rollers.speed * level.rollers.radius;  // 1600 rpm, 10 mm: 1.676 m/s
  for (const double degrees : {0.05, 0.1, 0.2, -0.1}) {
    const RunSummary r = run_skewed(std::to_string(degrees) + " deg", "8 s");
    const std::string where = std::to_string(degrees) + " deg: " + r.regime_evidence;
    ASSERT_EQ(r.regime, Regime::kOscillates) << where;
    ASSERT_TRUE(r.drift_speed && r.drift_speed_theory && r.period_trajectory) << where;
    const double drift = v_r * std::sin(0.5 * degrees * kDegree);
    EXPECT_NEAR(*r.drift_speed_theory, drift, 1e-12 * std::fabs(drift)) << where;
    // The drift over the run's second half: its slip along y decays within v_r / (mu_k g),
    // 0.6 s, so 4 s on it is the steady drift to a part in a thousand.
    EXPECT_NEAR(*r.drift_speed / drift, 1.0, 1e-3) << where;
    // The oscillation along x is the parallel rig's: the thick-plate period.
    const double thick = period_thick(level.rollers.spacing, level.friction.mu_k,
                                      compile_rig(level).plate.h_c, level.world.gravity);
    EXPECT_NEAR(*r.period_trajectory / thick, 1.0, 1e-4) << where;
  }
}

// Parallel rollers: the plate cannot drift, and nothing is reported for it.
TEST(SkewedRollers, ParallelRollersReportNoDrift) {
  const RunSummary r = run_experiment(compile_rig(test::minimal_without_sensor()), {});
  EXPECT_FALSE(r.drift_speed.has_value());
  EXPECT_FALSE(r.drift_speed_theory.has_value());
}

// A plate that drifts until its edge reaches the rollers' middles (where the lab's one contact a
// roller sits) is stopped with the reason, not left to fall: 1 degree drifts 14.6 mm/s, and the
// 60 mm plate's edge is there after about 2 s.
TEST(SkewedRollers, APlateThatDriftsOffTheContactsIsStoppedSayingWhy) {
  const RunSummary r = run_skewed("1 deg", "10 s");
  EXPECT_EQ(r.regime, Regime::kLost) << r.regime_evidence;
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_NE(r.failure->find("drifted"), std::string::npos) << *r.failure;
  EXPECT_NE(r.failure->find("rollers.skew"), std::string::npos) << *r.failure;
  EXPECT_LT(r.duration, 3.0);
}

TEST(SkewedRollers, ASkewBeyondTenDegreesIsRefused) {
  const std::vector<SceneOverride> keys{{"rollers.skew", "12 deg"}};
  try {
    test::minimal_without_sensor(keys);
    FAIL() << "a 12 degree skew was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("rollers.skew"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl
