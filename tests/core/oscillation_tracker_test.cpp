// The trajectory's own period and amplitude, against sampled cosines with a known answer.
#include "core/oscillation_tracker.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace fl {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(OscillationTracker, PeriodAndAmplitudeOfASampledCosine) {
  for (double period : {0.09, 0.79, 2.0}) {
    const double w = 2.0 * kPi / period;
    const double amplitude = 0.02;
    const double dt = period / 37.3;  // coarse, and not commensurate with the period
    OscillationTracker tracker;
    for (int i = 0; i <= 1000; ++i) {
      const double t = i * dt;
      tracker.add(t, amplitude * std::cos(w * t + 0.3), -amplitude * w * std::sin(w * t + 0.3));
    }
    const auto p = tracker.period();
    ASSERT_TRUE(p.has_value());
    // Cubic Hermite interpolation between samples 1/37 of a period apart: error ~ (w dt)^4.
    EXPECT_NEAR(p->slope / period - 1.0, 0.0, 1e-6) << period;
    for (double a : tracker.turning_amplitudes()) EXPECT_NEAR(a / amplitude - 1.0, 0.0, 1e-4);
    EXPECT_NEAR(*tracker.amplitude_drift_per_period(), 0.0, 1e-6);
    // Crossings alternate: half a period apart.
    const auto& c = tracker.crossings();
    for (std::size_t i = 1; i < c.size(); ++i)
      EXPECT_NEAR(c[i] - c[i - 1], 0.5 * period, 1e-5 * period);
  }
}

// A cosine about x = c (a tilted rig's plate): crossed about the centre given, it has its period;
// its centre, measured from the turning points, is c; and only the turning points after `since`
// count.
TEST(OscillationTracker, ACosineAboutAnotherCentreHasItsPeriodAndCentre) {
  const double period = 0.79, w = 2.0 * kPi / period, c = -0.0079, amplitude = 0.005;
  const double dt = 1e-3;
  OscillationTracker tracker(c);
  OscillationTracker level;  // crossings of x = 0: none, the plate never reaches it
  for (int i = 0; i <= 10000; ++i) {
    const double t = i * dt;
    const double x = c + amplitude * std::cos(w * t + 0.3);
    const double v = -amplitude * w * std::sin(w * t + 0.3);
    tracker.add(t, x, v);
    level.add(t, x, v);
  }
  ASSERT_TRUE(tracker.period().has_value());
  EXPECT_NEAR(tracker.period()->slope / period, 1.0, 1e-9);
  ASSERT_TRUE(tracker.centre().has_value());
  EXPECT_NEAR(*tracker.centre(), c, 1e-9);
  EXPECT_NEAR(*tracker.centre(5.0), c, 1e-9);
  EXPECT_FALSE(tracker.centre(10.0).has_value());
  for (double x : tracker.turning_positions()) EXPECT_NEAR(std::fabs(x - c), amplitude, 1e-9);
  EXPECT_FALSE(level.period().has_value());
}

TEST(OscillationTracker, DecayingAmplitudeIsMeasuredAsDrift) {
  const double period = 0.5, w = 2.0 * kPi / period, rate = 0.01;  // 1 % per second
  OscillationTracker tracker;
  for (int i = 0; i <= 20000; ++i) {
    const double t = i * 1e-3;
    const double a = 0.02 * (1.0 - rate * t);
    tracker.add(t, a * std::cos(w * t), -a * w * std::sin(w * t) - 0.02 * rate * std::cos(w * t));
  }
  // d(amplitude)/dt x T / A0 = -0.01 x 0.5.
  EXPECT_NEAR(*tracker.amplitude_drift_per_period(), -0.005, 2e-4);
}

// Straight lines through the centre between two samples, at 200 places in the step: the crossing
// is where the line crosses, to rounding. The interpolation's first guess (the secant) is then the
// root itself, give or take an ulp, and a guess that lands on the root, exactly or a fraction of
// an ulp from it, must be kept: refined further it stays put on the bracket's edge, where a
// bisection would take over and walk away (by 2^-20 of a step: once 5e-10 s on one crossing of a
// 4 s run, 4e-11 on its period).
TEST(OscillationTracker, ACrossingOnTheFirstGuessStaysThere) {
  const double dt = 1e-3, x0 = 1e-3;
  for (int k = 1; k <= 200; ++k) {
    const double x1 = -x0 * k / 37.0;
    const double speed = (x1 - x0) / dt;
    OscillationTracker tracker;
    tracker.add(0.0, x0, speed);
    tracker.add(dt, x1, speed);
    ASSERT_EQ(tracker.crossings().size(), 1u) << k;
    EXPECT_NEAR(tracker.crossings()[0], dt * x0 / (x0 - x1), 1e-18) << k;
  }
}

TEST(OscillationTracker, NoPeriodBeforeThreeCrossings) {
  OscillationTracker tracker;
  for (int i = 0; i < 10; ++i) tracker.add(i * 0.01, 0.01 + i * 1e-3, 0.1);
  EXPECT_FALSE(tracker.period().has_value());
  EXPECT_FALSE(tracker.amplitude_drift_per_period().has_value());
}

TEST(FitLine, ExactLineAndItsError) {
  const LinearFit f = fit_line({0, 1, 2, 3}, {1, 3, 5, 7});
  EXPECT_DOUBLE_EQ(f.slope, 2.0);
  EXPECT_DOUBLE_EQ(f.intercept, 1.0);
  EXPECT_NEAR(f.slope_std_error, 0.0, 1e-15);
  // Residuals +-e alternate: slope standard error from them.
  const LinearFit g = fit_line({0, 1, 2, 3}, {0.1, 0.9, 2.1, 2.9});
  EXPECT_GT(g.slope_std_error, 0.0);
}

}  // namespace
}  // namespace fl
