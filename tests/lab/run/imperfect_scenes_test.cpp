// scenes/imperfect/: one scene per imperfection of the paper's rig, each ending in the regime it
// declares, with the effect its header names checked against theory.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

struct SceneRun {
  Scene scene;
  RunSummary summary;
  RunRecording recording;
};

SceneRun run(const std::string& name) {
  SceneRun r;
  r.scene = test::scene_file(name);
  RunOptions options;
  options.record_hall = true;
  options.record_trajectory = true;
  r.summary = run_experiment(r.scene, options, &r.recording);
  if (name.starts_with("imperfect/")) {
    EXPECT_TRUE(r.scene.expected_regime.has_value()) << name;
    EXPECT_EQ(r.summary.regime, r.scene.expected_regime.value_or(Regime::kLost))
        << name << ": " << r.summary.regime_evidence;
  }
  return r;
}

// The largest Hall reading above the baseline from time `from` [s] on [counts].
int pulse_height(const RunRecording& r, double from) {
  int most = 0;
  for (const HallSample& s : r.hall)
    if (s.t_us * 1e-6 >= from) most = std::max(most, static_cast<int>(s.adc) - 511);
  return most;
}

TEST(ImperfectScenes, RunoutAboveTheThresholdMakesThePlateJump) {
  const SceneRun r = run("imperfect/runout.yaml");
  ASSERT_TRUE(r.summary.runout && r.summary.runout_threshold);
  EXPECT_GT(*r.summary.runout, *r.summary.runout_threshold);
  ASSERT_TRUE(r.summary.jumps.has_value());
  EXPECT_GT(*r.summary.jumps, 100);
  // The periods the estimator kept give the trajectory's period. How many a jump spoils is a
  // matter of which jumps a chaotic hopping plate makes (tests/lab/run/jump_periods_test.cpp holds
  // the share over neighbouring set-ups).
  const EstimatorReport& e = *r.summary.estimator;
  EXPECT_GE(e.periods_used, 10);
  EXPECT_LT(std::fabs(e.period - *r.summary.period_trajectory), 3.0 * e.period_std_error);
}

TEST(ImperfectScenes, WarmingRollersShortenThePeriodAsTheirMuKRises) {
  const SceneRun r = run("imperfect/rollers-warming.yaml");
  const CompiledRig rig = compile_rig(r.scene);
  ASSERT_TRUE(rig.warming && r.summary.warming);
  for (const EstimatedPeriod& p : r.recording.periods) {
    const double mu = rig.warming->mu_k(0.5 * (p.start + p.end));
    EXPECT_NEAR(p.period / period_thick(rig.rollers.spacing, mu, rig.plate.h_c, rig.world.gravity),
                1.0, 2e-3)
        << p.start;
  }
  const WarmingReport& w = *r.summary.warming;
  ASSERT_TRUE(w.first_10_periods && w.whole_run);
  EXPECT_GT(w.first_10_periods->mu_k, w.mu_k_cold_paper_formula);
  EXPECT_GT(w.whole_run->mu_k, w.first_10_periods->mu_k);
}

TEST(ImperfectScenes, APlateAgainstATowerKeepsItsPeriodAndShrinksThePulses) {
  const SceneRun r = run("imperfect/plate-sideways.yaml");
  // It reaches the tower (the towers' inner faces 28.1 mm out, the plate 24 mm wide each side:
  // 4.1 mm) and stays beside it, turned a little against it.
  double farthest = 0.0;
  for (const TrajectoryRow& row : r.recording.trajectory)
    farthest = std::max(farthest, std::fabs(row.plate.y));
  EXPECT_NEAR(farthest, 4.1e-3, 0.4e-3);
  EXPECT_GT(std::fabs(r.recording.trajectory.back().plate.y), 2e-3);
  const SceneRun centred = run("paper-rig.yaml");
  EXPECT_NEAR(*r.summary.period_trajectory / *centred.summary.period_trajectory, 1.0, 2e-4);
  EXPECT_LT(pulse_height(r.recording, 5.0), pulse_height(centred.recording, 5.0) / 4);
}

TEST(ImperfectScenes, AFastClockLengthensEveryPeriodAndLowersMuK) {
  const SceneRun r = run("imperfect/clock-fast.yaml");
  ASSERT_TRUE(r.summary.clock_error.has_value());
  const double e = *r.summary.clock_error;
  const EstimatorReport& est = *r.summary.estimator;
  EXPECT_NEAR(est.period / *r.summary.period_trajectory, 1.0 + e,
              3.0 * est.period_std_error / est.period + 5e-5);
  EXPECT_FALSE(r.summary.estimator_disagreement.has_value()) << *r.summary.estimator_disagreement;
}

}  // namespace
}  // namespace fl
