// Rollers of different radii (rollers.radius: [a_0, a_1]) on axes at one height, l apart: the
// plate rests on the common tangent above the two circles, which rises by theta = asin((a_1 -
// a_0) / l), its tangent points l cos(theta) apart. The plate is then on a tilted rig (written out
// here, as tests/lab/run/tilted_rig_test.cpp has it): with the table's tilt t added, tau = t +
// theta,
//   Omega^2 = 2 mu_k g cos(tau) / (l cos(theta) - 2 mu_k h_c),
//   x_eq = -(l cos(theta) - 2 mu_k h_c) tan(tau) / (2 mu_k)
// along the tangent from the midpoint of the tangent points. Every plate of the grid oscillates
// with the trajectory's period within 0.01 % of 2 pi / Omega and its centre within 0.05 mm of x_eq.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kSpacing = 0.089;
constexpr double kDegree = std::numbers::pi / 180.0;

TEST(UnequalRadii, ThePlateOnTheirTangentIsOnATiltedRig) {
  int cases = 0;
  for (const auto& [a_0, a_1] : {std::pair{10.0, 10.5}, std::pair{10.0, 12.0},
                                 std::pair{12.0, 10.0}, std::pair{10.0, 15.0}}) {
    for (const double table_deg : {0.0, -3.0}) {
      for (const double mu : {0.29, 1.0}) {
        const std::vector<SceneOverride> keys{
            {"rollers.diameter", fmt::format("[{} mm, {} mm]", 2 * a_0, 2 * a_1)},
            {"world.tilt", fmt::format("{} deg", table_deg)},
            {"friction.mu_k", fmt::format("{}", mu)},
            {"plate.length", "300 mm"},
            {"world.duration", "12 s"},
        };
        Scene scene = test::minimal_without_sensor(keys);
        const double h_c = compile_rig(scene).plate.h_c;
        const double theta = std::asin((a_1 - a_0) * 1e-3 / kSpacing);
        const double tau = table_deg * kDegree + theta;
        const double arm = kSpacing * std::cos(theta) - 2.0 * mu * h_c;
        const double omega = std::sqrt(2.0 * mu * 9.81 * std::cos(tau) / arm);
        const double centre = -arm * std::tan(tau) / (2.0 * mu);
        scene.plate.offset = centre + 0.010;  // released 10 mm from the centre
        const RunSummary r = run_experiment(compile_rig(scene), {});
        const std::string where = fmt::format("radii {} and {} mm, table {} deg, mu_k {}: {}", a_0,
                                              a_1, table_deg, mu, r.regime_evidence);
        ASSERT_EQ(r.regime, Regime::kOscillates) << where;
        ASSERT_TRUE(r.period_trajectory && r.oscillation_centre) << where;
        EXPECT_NEAR(*r.period_trajectory * omega / (2.0 * std::numbers::pi), 1.0, 1e-4) << where;
        EXPECT_NEAR(*r.oscillation_centre, centre, 0.05e-3) << where;
        ++cases;
      }
    }
  }
  EXPECT_EQ(cases, 16);
}

// The two rollers' surfaces move at their own speeds, omega a_0 and omega a_1: under coulomb
// friction that changes nothing while both slip (above); the summary's slip margin is the
// slower surface's against the plate's largest speed.
TEST(UnequalRadii, TheSlipMarginIsTheSlowerSurfaces) {
  const std::vector<SceneOverride> keys{{"rollers.diameter", "[20 mm, 10 mm]"},
                                        {"world.duration", "4 s"}};
  const Scene scene = test::minimal_without_sensor(keys);
  const RunSummary r = run_experiment(compile_rig(scene), {});
  ASSERT_GT(r.plate_speed_max, 0.0);
  EXPECT_NEAR(r.slip_margin, scene.rollers.speed * 0.005 / r.plate_speed_max, 1e-12);
}

TEST(UnequalRadii, TwoRadiiWithADriveAreRefused) {
  const std::vector<SceneOverride> keys{{"rollers.diameter", "[20 mm, 22 mm]"}};
  try {
    test::scene_file("paper-rig.yaml", keys);
    FAIL() << "two radii with the paper rig's drive were accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("ideal drive"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl
