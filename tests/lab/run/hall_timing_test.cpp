// The sensor's error budget (sensor/hall_timing.hpp) against the rig's estimator: over sixteen
// seeds (the sensor's noise and jitter drawn anew) the Hall period's departure from the
// trajectory's own period scatters as the budget's one sigma predicts and never leaves its bound.
#include "sensor/hall_timing.hpp"

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

struct Case {
  std::string material;
  std::string spacing;
  std::string offset = "20 mm";  // the release: toward the sensor (+) or away from it
};

class HallTimingBudget : public ::testing::TestWithParam<Case> {};

TEST_P(HallTimingBudget, PredictsTheEstimatorsScatterAndBoundsIt) {
  const Case c = GetParam();
  constexpr int kSeeds = 16;
  std::vector<double> departures;
  std::optional<HallTiming> timing;
  double period = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    // Hall and trajectory read the same simulated motion: the step's bias is in both, and their
    // difference is the sensor's and the estimator's alone.
    const std::vector<SceneOverride> overrides = {
        {"plate.material", c.material}, {"rollers.spacing", c.spacing},
        {"plate.length", "300 mm"},     {"plate.offset", c.offset},
        {"world.duration", "20 s"},     {"world.seed", std::to_string(seed)}};
    const CompiledRig rig = compile_rig(test::scene_file("minimal.yaml", overrides));
    timing = predict_hall_timing(rig, 12.0);
    ASSERT_TRUE(timing.has_value());
    period = *rig.period_thick;
    const RunSummary s = run_experiment(rig, RunOptions{});
    // The budget counts the periods the estimator times.
    ASSERT_TRUE(s.estimator && s.estimator->periods_used == timing->periods && s.period_trajectory)
        << "the estimator timed " << (s.estimator ? s.estimator->periods_used : 0)
        << " periods, the budget counts " << timing->periods;
    departures.push_back(s.estimator->period / *s.period_trajectory - 1.0);
  }
  double sum2 = 0.0, worst = 0.0;
  for (double d : departures) {
    sum2 += d * d;
    worst = std::max(worst, std::fabs(d));
  }
  const double rms = std::sqrt(sum2 / kSeeds);
  const double sigma = timing->crossing_sd / (timing->periods * period);
  // The rms of 16 draws is within 1/sqrt(2 x 16) = 18 % of sigma at one standard error: three of
  // them either way.
  EXPECT_GT(rms, 0.45 * sigma) << "the budget is too pessimistic";
  EXPECT_LT(rms, 1.55 * sigma) << "the budget misses an error";
  EXPECT_LE(worst, timing->period_error);
}

INSTANTIATE_TEST_SUITE_P(Materials, HallTimingBudget,
                         ::testing::Values(Case{"cardboard", "120 mm"}, Case{"cardboard", "200 mm"},
                                           Case{"paper", "160 mm"}, Case{"lego", "89 mm"},
                                           Case{"rigid-foam", "89 mm"},
                                           Case{"lego", "89 mm", "-20 mm"}),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           const Case& c = param_info.param;
                           std::string name =
                               c.material + "_" + c.spacing + "_released_at_" +
                               (c.offset[0] == '-' ? "minus_" + c.offset.substr(1) : c.offset);
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace fl
