// The rig's estimator on the host (lab/host_estimator), on a synthetic Hall signal with a known
// truth: each pulse at a turning point of the plate, the periods at the true period, and the same
// on a clock that wraps around 2^32 us in the middle of the signal, where the pulses' times go on
// past the wrap instead of starting again from zero.
#include "estimator/host_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "estimator/synthetic_hall.hpp"

namespace fl {
namespace {

constexpr double kWrapSeconds = 4294.967296;  // 2^32 us

HostEstimator run(const test::HallSamples& samples) {
  HostEstimator host{fl_estimator::Config()};
  for (std::size_t i = 0; i < samples.adc.size(); ++i) host.add(samples.t_us[i], samples.adc[i]);
  host.finish();
  return host;
}

// The distance from t to the nearest time in `truth`.
double miss(const std::vector<double>& truth, double t) {
  double best = 1e9;
  for (double u : truth) best = std::min(best, std::abs(u - t));
  return best;
}

TEST(HostEstimator, PulsesAtTheTurningPointsAndPeriodsAtTheTruePeriod) {
  test::HallSignal s;
  s.duration_s = 20.0;
  const HostEstimator host = run(test::generate(s));
  const std::vector<double> turns = test::turning_times(s, 0.0, s.duration_s);
  ASSERT_GE(host.pulses().size(), 20u);
  // One pulse per period, timed at the turning point within a sample (1 ms).
  for (const EstimatedPulse& p : host.pulses()) {
    EXPECT_LT(miss(turns, p.time), 1e-3) << p.time;
    EXPECT_LT(p.rise, p.time);
    EXPECT_GT(p.fall, p.time);
  }
  ASSERT_GE(host.periods().size(), 18u);
  for (const EstimatedPeriod& p : host.periods()) {
    EXPECT_EQ(p.status, fl_estimator::kAccepted);
    EXPECT_NEAR(p.period, s.period_s, 0.0005 * s.period_s);
    EXPECT_NEAR(p.end - p.start, p.period, 1e-6);
  }
}

TEST(HostEstimator, TimesGoOnPastAWrapOfTheClock) {
  test::HallSignal s;
  s.duration_s = 20.0;
  const HostEstimator reference = run(test::generate(s));
  const std::uint32_t start = 4294967295u - 7000000u;  // the clock wraps 7 s in
  s.t0_us = start;
  const HostEstimator wrapped = run(test::generate(s));
  const double offset = start * 1e-6;
  ASSERT_EQ(wrapped.pulses().size(), reference.pulses().size());
  for (std::size_t i = 0; i < reference.pulses().size(); ++i)
    EXPECT_NEAR(wrapped.pulses()[i].time - offset, reference.pulses()[i].time, 1e-6) << i;
  ASSERT_EQ(wrapped.periods().size(), reference.periods().size());
  bool crossed = false;
  for (std::size_t i = 0; i < reference.periods().size(); ++i) {
    const EstimatedPeriod& p = wrapped.periods()[i];
    EXPECT_NEAR(p.end - offset, reference.periods()[i].end, 1e-6) << i;
    EXPECT_EQ(p.period, reference.periods()[i].period) << i;
    crossed = crossed || (p.start < kWrapSeconds && p.end > kWrapSeconds);
  }
  EXPECT_TRUE(crossed) << "no period spans the wrap";
}

TEST(HostEstimator, StatisticsIfFinishedLeaveTheEstimatorRunning) {
  test::HallSignal s;
  s.duration_s = 12.0;
  const test::HallSamples samples = test::generate(s);
  HostEstimator host{fl_estimator::Config()};
  for (std::size_t i = 0; i < samples.adc.size(); ++i) host.add(samples.t_us[i], samples.adc[i]);
  const fl_estimator::Stats now = host.stats_if_finished();
  const std::size_t periods = host.periods().size();
  EXPECT_EQ(host.stats_if_finished().periods_used, now.periods_used);  // nothing was consumed
  host.finish();
  EXPECT_EQ(host.estimator().stats().periods_used, now.periods_used);
  EXPECT_GE(host.periods().size(), periods);
  EXPECT_NEAR(now.period_s, s.period_s, 0.0005 * s.period_s);
}

}  // namespace
}  // namespace fl
