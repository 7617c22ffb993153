// The pulses a video's Hall plot marks, against the plate's own motion: in the quickstart's clip
// of the paper's rig (4 s), every pulse the estimator learned the signal from and every pulse it
// timed lies at a turning point of the plate on the sensor's side, and every such turning point
// whose pulse has ended is marked, once. The period the plot's panel shows from the timed pulses
// before the estimator's own (provisional) matches the plate's turning points' spacing.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "lab/run/hall_estimator.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

struct Clip {
  std::vector<double> turns;     // s, maxima of the plate's x (the sensor's side), t = 0 included
  std::vector<double> learning;  // s
  std::vector<double> timed;     // s
  std::vector<double> provisional;  // s
  int periods_used = 0;
};

Clip quickstart_clip() {
  Scene scene = test::scene_file("paper-rig.yaml");
  scene.world.duration = 4.0;  // the quickstart's clip
  Clip clip;
  std::vector<std::pair<double, double>> x;  // t, plate x
  RunOptions options;
  const HallEstimator* estimator = nullptr;
  options.observer = [&](const StepView& view) {
    x.emplace_back(view.t, view.plate.x);
    estimator = view.estimator;
    if (estimator != nullptr) {
      clip.learning = estimator->learning_pulse_times();
      clip.timed = estimator->pulse_times();
      clip.provisional = estimator->provisional_periods();
      clip.periods_used = estimator->report().periods_used;
    }
  };
  run_experiment(compile_rig(scene), options, nullptr);
  // Released at rest at its largest offset (toward the sensor): the first turning point is t = 0.
  if (x.size() > 1 && x[0].second >= x[1].second) clip.turns.push_back(x[0].first);
  for (std::size_t i = 1; i + 1 < x.size(); ++i)
    if (x[i].second > x[i - 1].second && x[i].second >= x[i + 1].second && x[i].second > 0.0)
      clip.turns.push_back(x[i].first);
  return clip;
}

double nearest(const std::vector<double>& times, double t) {
  double best = 1e9;
  for (const double u : times) best = std::min(best, std::fabs(u - t));
  return best;
}

TEST(HallPulses, EveryMarkedPulseIsATurningPointAndEveryEndedTurnIsMarked) {
  const Clip clip = quickstart_clip();
  ASSERT_GE(clip.turns.size(), 5u);
  std::vector<double> marked = clip.learning;
  marked.insert(marked.end(), clip.timed.begin(), clip.timed.end());
  // Measured: a timed pulse within 0.3 ms of its turning point (the estimator interpolates the
  // timing level's crossings between 1 kHz samples); the learning pulse cut by the start sits at
  // the first sample, t = 1 ms, beside the release at t = 0.
  for (const double t : clip.timed)
    EXPECT_LT(nearest(clip.turns, t), 1e-3) << "timed pulse at t = " << t;
  for (const double t : clip.learning)
    EXPECT_LT(nearest(clip.turns, t), 2e-3) << "learning pulse at t = " << t;
  // Each turning point is marked once, but for one still inside its pulse at the clip's end (a
  // pulse ends about 0.05 s after its turning point at this amplitude).
  std::size_t ended = 0;
  for (const double turn : clip.turns) {
    if (turn > 4.0 - 0.1) continue;
    ++ended;
    EXPECT_EQ(std::count_if(marked.begin(), marked.end(),
                            [&](double t) { return std::fabs(t - turn) < 2e-3; }),
              1)
        << "turning point at t = " << turn;
  }
  EXPECT_EQ(marked.size(), ended);
  EXPECT_GE(clip.learning.size(), 1u);  // the signal is learned from the first swings
}

TEST(HallPulses, TheQuickstartClipShowsAPeriod) {
  const Clip clip = quickstart_clip();
  // Before its own periods (from 5 timed pulses) the estimator gives the timed pulses' intervals.
  ASSERT_TRUE(clip.periods_used > 0 || !clip.provisional.empty());
  ASSERT_FALSE(clip.provisional.empty());
  // Against the plate's turning points: each provisional period is the spacing of the two turning
  // points its pulses mark (one pulse per period at this sensor). Measured within 0.3 ms, as the
  // pulses' times.
  for (std::size_t i = 0; i < clip.provisional.size(); ++i) {
    const auto turn =
        std::min_element(clip.turns.begin(), clip.turns.end(), [&](double a, double b) {
          return std::fabs(a - clip.timed[i]) < std::fabs(b - clip.timed[i]);
        });
    ASSERT_NE(turn + 1, clip.turns.end());
    EXPECT_NEAR(clip.provisional[i], *(turn + 1) - *turn, 1e-3) << "period " << i;
  }
}

}  // namespace
}  // namespace fl
