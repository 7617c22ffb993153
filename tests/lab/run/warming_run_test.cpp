// Rollers warming after liquid nitrogen, run on the minimal rig: each period the rig's estimator
// measures is the thick plate's at the rollers' mu_k at that time (mu_k changes slowly against a
// period), the cold hold gives the 77 K period, and the mu_k a student computes drifts from the
// cold value as the windows widen.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

TEST(WarmingRun, EachPeriodIsTheThickPlatesAtTheRollersMuKThen) {
  const Scene s = test::scene_file("minimal.yaml",
                                   std::vector<SceneOverride>{
                                       {"world.duration", "60 s"},
                                       {"friction.temperature", "77 K"},
                                       {"friction.warming", "{time_constant: 20 s, hold: 10 s}"},
                                   });
  const CompiledRig rig = compile_rig(s);
  ASSERT_TRUE(rig.warming.has_value());
  RunOptions options;
  options.record_hall = true;
  RunRecording recording;
  const RunSummary summary = run_experiment(rig, options, &recording);
  ASSERT_EQ(summary.regime, Regime::kOscillates) << summary.regime_evidence;
  ASSERT_GT(recording.periods.size(), 50u);
  double worst = 0.0;
  for (const EstimatedPeriod& p : recording.periods) {
    ASSERT_EQ(p.status, fl_estimator::kAccepted) << p.start;
    // mu_k at the period's middle: over one period it moves by at most 4 % (the steepest, just
    // after the hold), and a linear change averages to its middle value.
    const double mu = rig.warming->mu_k(0.5 * (p.start + p.end));
    const double expected = period_thick(rig.rollers.spacing, mu, rig.plate.h_c, rig.world.gravity);
    worst = std::max(worst, std::fabs(p.period / expected - 1.0));
  }
  // Measured: 1.1e-3 at worst, where mu_k changes fastest (the estimator times a turning point by
  // its pulse's middle, which a changing amplitude skews a little; its scatter on steady rollers
  // is a few 1e-4).
  EXPECT_LT(worst, 2e-3);

  ASSERT_TRUE(summary.warming.has_value());
  const WarmingReport& w = *summary.warming;
  EXPECT_EQ(w.mu_k_start, 0.20);
  EXPECT_NEAR(w.end_temperature, 300.0 - 223.0 * std::exp(-50.0 / 20.0), 1e-9);
  // The first 10 periods (0.94 s each) all fall in the 10 s hold: the cold rollers' mu_k.
  ASSERT_TRUE(w.first_10_periods && w.first_30_s && w.whole_run);
  EXPECT_EQ(w.first_10_periods->periods, 10);
  EXPECT_NEAR(w.first_10_periods->mu_k / w.mu_k_cold_paper_formula, 1.0, 2e-3);
  EXPECT_GT(w.first_30_s->mu_k, w.first_10_periods->mu_k * 1.05);
  EXPECT_GT(w.whole_run->mu_k, w.first_30_s->mu_k);
  EXPECT_EQ(w.whole_run->periods, summary.estimator->periods_used);
}

}  // namespace
}  // namespace fl
