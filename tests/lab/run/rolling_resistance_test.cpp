// Rolling resistance (rollers.rolling_resistance): each roller presses the plate through a
// pressure centre delta ahead of its top, outward for rollers turning inward, so the plate rests
// on contacts l + 2 delta apart and, with coulomb friction,
//   T = pi sqrt(2 (l + 2 delta - 2 mu_k h_c) / (mu_k g))
// (written out here). A spacing series of such a rig lies on a line T^2 = s l + c whose slope
// gives mu_k and whose intercept reads h_c - delta / mu_k: the fit cannot tell delta from h_c.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/thick_plate_fit.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

double closed_form(double spacing, double delta, double mu, double h_c) {
  return std::numbers::pi * std::sqrt(2.0 * (spacing + 2.0 * delta - 2.0 * mu * h_c) / (mu * 9.81));
}

RunSummary run(double spacing, double delta_mm, double mu, double* h_c) {
  const std::vector<SceneOverride> keys{
      {"rollers.spacing", fmt::format("{} mm", spacing * 1e3)},
      {"rollers.rolling_resistance", fmt::format("{} mm", delta_mm)},
      {"friction.mu_k", fmt::format("{}", mu)},
      {"world.duration", "15 s"},
  };
  const CompiledRig rig = compile_rig(test::minimal_without_sensor(keys));
  *h_c = rig.plate.h_c;
  return run_experiment(rig, {});
}

TEST(RollingResistance, ThePeriodIsTheClosedFormsWithTheContactsMovedOut) {
  for (const double mu : {0.29, 1.0}) {
    for (const double delta_mm : {0.0, 0.5, 1.0, 2.0}) {
      double h_c = 0.0;
      const RunSummary r = run(0.089, delta_mm, mu, &h_c);
      const std::string where = fmt::format("mu_k {}, delta {} mm", mu, delta_mm);
      ASSERT_EQ(r.regime, Regime::kOscillates) << where << ": " << r.regime_evidence;
      ASSERT_TRUE(r.period_trajectory && r.oscillation_centre) << where;
      EXPECT_NEAR(*r.period_trajectory / closed_form(0.089, 1e-3 * delta_mm, mu, h_c), 1.0, 1e-4)
          << where;
      EXPECT_NEAR(*r.oscillation_centre, 0.0, 0.05e-3) << where;
    }
  }
}

TEST(RollingResistance, ASpacingSeriesReadsHcLessDeltaOverMuK) {
  const double mu = 0.29, delta = 1e-3;
  std::vector<SpacingPeriod> series;
  double h_c = 0.0;
  for (const double spacing : {0.060, 0.075, 0.089, 0.105, 0.120}) {
    const RunSummary r = run(spacing, 1e3 * delta, mu, &h_c);
    ASSERT_TRUE(r.period_trajectory) << spacing;
    series.push_back({spacing, *r.period_trajectory, 1e-5, std::nullopt});
  }
  const ThickPlateFit fit = fit_thick_plate(series);
  ASSERT_TRUE(fit.mu_k && fit.h_c);
  EXPECT_NEAR(*fit.mu_k / mu, 1.0, 1e-4);
  // 2.58 mm of h_c less 3.45 mm of delta / mu_k: the fit reads -0.87 mm.
  EXPECT_NEAR(*fit.h_c, h_c - delta / mu, 0.02e-3);
}

}  // namespace
}  // namespace fl
