// A tilted rig (world.tilt) in the Bullet world against the closed forms written out here: with
// coulomb friction and both rollers slipping, the slope's pull -g sin(tilt) acts at the centre of
// mass and only shifts where the net friction balances it, while g cos(tilt) presses the plate on
// its rollers, so
//   Omega^2 = 2 mu_k g cos(tilt) / (l - 2 mu_k h_c),   x_eq = -(l - 2 mu_k h_c) tan(tilt) / (2
//   mu_k)
// and a roller unloads at |x| = l/2 - mu_k h_c as on a level rig. Over tilts of -5 to +5 degrees,
// mu_k 0.05 to 1.7 and h_c up to 5 mm, every plate that stays on both rollers oscillates with the
// trajectory's period within 0.01 % of 2 pi / Omega and its centre within 0.05 mm of x_eq; one
// whose centre and amplitude reach the unloading offset tips.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kSpacing = 0.089;
constexpr double kAmplitude = 0.010;  // m, the plate released this far from the centre

TEST(TiltedRig, PeriodAndCentreMatchTheClosedFormsOrThePlateTips) {
  int oscillating = 0, tipping = 0;
  for (const double tilt_deg : {-5.0, -2.0, 0.0, 2.0, 5.0}) {
    for (const double mu : {0.05, 0.29, 1.7}) {
      for (const double thickness_mm : {1.0, 5.0, 10.0}) {
        const double tilt = tilt_deg * std::numbers::pi / 180.0;
        const std::vector<SceneOverride> keys{
            {"world.tilt", fmt::format("{} deg", tilt_deg)},
            {"friction.mu_k", fmt::format("{}", mu)},
            {"plate.thickness", fmt::format("{} mm", thickness_mm)},
            {"plate.length", "300 mm"},
        };
        Scene scene = test::minimal_without_sensor(keys);
        // h_c from the plate's parts (the slab and the magnets), and the closed forms.
        const double h_c = compile_rig(scene).plate.h_c;
        const double arm = kSpacing - 2.0 * mu * h_c;
        const double g = 9.81 * std::cos(tilt);
        const double omega = std::sqrt(2.0 * mu * g / arm);
        const double centre = -arm * std::tan(tilt) / (2.0 * mu);
        const double period = 2.0 * std::numbers::pi / omega;
        const bool stays = std::fabs(centre) + kAmplitude < 0.5 * arm;
        // Released 10 mm from the centre, or, where the centre itself lies beyond a roller's
        // unloading offset, 5 mm inside that offset, the slope's side.
        scene.plate.offset = std::fabs(centre) < 0.5 * arm
                                 ? centre + kAmplitude
                                 : std::copysign(0.5 * arm - 0.005, centre);
        scene.world.duration = std::max(10.0, 12.0 * period);
        const CompiledRig rig = compile_rig(scene);
        const RunSummary r = run_experiment(rig, {});
        const std::string where = fmt::format("tilt {} deg, mu_k {}, h_c {} mm: {}", tilt_deg, mu,
                                              h_c * 1e3, r.regime_evidence);
        if (!stays) {
          EXPECT_EQ(r.regime, Regime::kTips) << where;
          ++tipping;
          continue;
        }
        ++oscillating;
        ASSERT_EQ(r.regime, Regime::kOscillates) << where;
        ASSERT_TRUE(r.period_trajectory && r.oscillation_centre) << where;
        EXPECT_NEAR(*r.period_trajectory / period, 1.0, 1e-4) << where;
        EXPECT_NEAR(*r.oscillation_centre, centre, 0.05e-3) << where;
        // The run's own theory says the same.
        ASSERT_TRUE(r.oscillation_centre_theory && r.period_thick) << where;
        EXPECT_NEAR(*r.oscillation_centre_theory, centre, 1e-12) << where;
        EXPECT_NEAR(*r.period_thick / period, 1.0, 1e-12) << where;
      }
    }
  }
  // The grid holds both: plates that stay on and plates the slope tips off.
  EXPECT_GT(oscillating, 30);
  EXPECT_GT(tipping, 2);
}

}  // namespace
}  // namespace fl
