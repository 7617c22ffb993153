// The plate's motion cut into cycles, against signals with a known answer: a sine (period,
// amplitude, no stick), a chirp (each cycle's own period, and the rollers' speed averaged over
// it), a sine clipped to flat tops (amplitude = the clip, period unchanged), and the exact
// stick-slip cycle of core/stick_slip_cycle.hpp (its period, amplitude and stick time).
#include "core/cycle_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/stick_slip_cycle.hpp"

namespace fl {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CycleTracker, SineGivesItsPeriodAndAmplitudeAndNoStick) {
  const double period = 0.79, amplitude = 0.02, w = 2.0 * kPi / period;
  const double dt = period / 200.3;  // not commensurate with the period
  const double surface = 0.5;        // m/s, far above the plate's largest speed A w = 0.16 m/s
  CycleTracker tracker;
  for (int i = 0; i <= 20000; ++i) {
    const double t = i * dt;
    tracker.add(t, amplitude * std::sin(w * t + 0.4), amplitude * w * std::cos(w * t + 0.4),
                {surface, -surface});
  }
  const auto& cycles = tracker.cycles();
  ASSERT_GE(cycles.size(), 20u);
  for (const CycleRecord& c : cycles) {
    // The crossing is placed linearly where x'' = 0: each crossing's phase is off by at most
    // (w dt)^3 / 24, the period by twice that.
    EXPECT_NEAR(c.period / period, 1.0, std::pow(w * dt, 3) / 12.0 / (2.0 * kPi));
    // Samples w dt = 2 pi / 200 apart miss the peak by at most A (1 - cos(w dt / 2)).
    EXPECT_NEAR(c.amplitude / amplitude, 1.0, 1.3e-4);
    EXPECT_NEAR(c.x_max + c.x_min, 0.0, 2.0 * amplitude * (1.0 - std::cos(0.5 * w * dt)));
    EXPECT_NEAR(c.surface_speed_mean, surface, 1e-12);
    EXPECT_EQ(c.stick_duration, 0.0);
    EXPECT_FALSE(c.stuck());
  }
  // The first cycle opens at the first upward crossing: w t + 0.4 = 2 pi.
  EXPECT_NEAR(cycles.front().start, (2.0 * kPi - 0.4) / w, std::pow(w * dt, 3) / 24.0 / w);
}

TEST(CycleTracker, ChirpGivesEachCycleItsOwnPeriodAndMeanSpeed) {
  // x = A sin(phi), phi = 2 pi (f0 t + k t^2 / 2): upward crossings where phi = 2 pi n, at
  // t_n = (sqrt(f0^2 + 2 k n) - f0) / k. The rollers' speed rises linearly: u = u0 + c t, whose
  // mean over a cycle is its value at the cycle's middle.
  const double f0 = 1.0, k = 0.1, amplitude = 0.015, dt = 1e-3;
  const double u0 = 0.2, c = 0.01;
  const auto crossing = [&](int n) { return (std::sqrt(f0 * f0 + 2.0 * k * n) - f0) / k; };
  CycleTracker tracker;
  for (int i = 0; i <= 30000; ++i) {
    const double t = i * dt;
    const double phi = 2.0 * kPi * (f0 * t + 0.5 * k * t * t);
    const double dphi = 2.0 * kPi * (f0 + k * t);
    const double u = u0 + c * t;
    tracker.add(t, amplitude * std::sin(phi), amplitude * dphi * std::cos(phi), {u, -u});
  }
  const auto& cycles = tracker.cycles();
  ASSERT_GE(cycles.size(), 70u);
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    const int n = static_cast<int>(i) + 1;  // t = 0 is the crossing n = 0 (not counted: no sample
                                            // before it)
    const double start = crossing(n), end = crossing(n + 1);
    EXPECT_NEAR(cycles[i].start, start, 1e-7) << i;
    EXPECT_NEAR(cycles[i].period, end - start, 2e-7) << i;
    EXPECT_NEAR(cycles[i].amplitude / amplitude, 1.0, 5e-4) << i;
    EXPECT_NEAR(cycles[i].surface_speed_mean, u0 + c * 0.5 * (start + end), 1e-9) << i;
  }
  // The period shortens cycle after cycle.
  EXPECT_LT(cycles.back().period, 0.5 * cycles.front().period);
}

TEST(CycleTracker, ClippedSineHasTheClipAsAmplitudeAndTheSinesPeriod) {
  const double period = 0.5, amplitude = 0.02, clip = 0.012, w = 2.0 * kPi / period;
  const double dt = 1e-3;
  CycleTracker tracker;
  for (int i = 0; i <= 10000; ++i) {
    const double t = i * dt;
    const double free = amplitude * std::sin(w * t);
    const bool flat = std::fabs(free) >= clip;
    const double x = std::clamp(free, -clip, clip);
    tracker.add(t, x, flat ? 0.0 : amplitude * w * std::cos(w * t), {1.0, -1.0});
  }
  const auto& cycles = tracker.cycles();
  ASSERT_GE(cycles.size(), 15u);
  for (const CycleRecord& c : cycles) {
    EXPECT_NEAR(c.period / period, 1.0, 1e-7);
    EXPECT_DOUBLE_EQ(c.amplitude, clip);
    EXPECT_DOUBLE_EQ(c.x_max, clip);
    EXPECT_DOUBLE_EQ(c.x_min, -clip);
    EXPECT_FALSE(c.stuck());  // resting on the flat tops is not moving with a roller
  }
}

TEST(CycleTracker, StickSlipCycleGivesItsPeriodAmplitudeAndStickTime) {
  // The exact stick-slip cycle (core/stick_slip_cycle.hpp): stuck to roller 0 at +v_r from -x_b
  // to x_b, a harmonic arc out and back to x_b at -v_r, stuck to roller 1 back to -x_b, an arc
  // out and back to -x_b at +v_r.
  FrictionLaw law;
  law.mu_k = 0.29;
  law.mu_s = 0.35;
  const PlateOnRollers plate{0.089, 0.0, 9.81};
  const double v_r = 0.1;
  const StickSlipCycle cycle = stick_slip_cycle(law, plate, v_r);
  ASSERT_GT(cycle.break_offset, 0.0);
  const double w = cycle.omega, xb = cycle.break_offset, S = cycle.stick_duration;
  const double L = cycle.slip_duration, P = cycle.period;
  const auto state = [&](double t, double& x, double& v) {
    double s = std::fmod(t, P);
    if (s < S) {
      x = -xb + v_r * s;
      v = v_r;
    } else if ((s -= S) < L) {
      x = xb * std::cos(w * s) + v_r / w * std::sin(w * s);
      v = -xb * w * std::sin(w * s) + v_r * std::cos(w * s);
    } else if ((s -= L) < S) {
      x = xb - v_r * s;
      v = -v_r;
    } else {
      s -= S;
      x = -xb * std::cos(w * s) - v_r / w * std::sin(w * s);
      v = xb * w * std::sin(w * s) - v_r * std::cos(w * s);
    }
  };
  const double dt = 1e-4;
  // A tight stick tolerance: the arcs leave the rollers' speed within 0.04 ms of each stick.
  CycleTracker tracker(0.0, 1e-4);
  for (int i = 0; i <= 100000; ++i) {
    const double t = i * dt;
    double x = 0.0, v = 0.0;
    state(t, x, v);
    tracker.add(t, x, v, {v_r, -v_r});
  }
  const auto& cycles = tracker.cycles();
  ASSERT_GE(cycles.size(), 8u);
  for (const CycleRecord& c : cycles) {
    // The upward crossing falls in the stick to roller 0, where x is linear in t: exact.
    EXPECT_NEAR(c.period / P, 1.0, 1e-9);
    EXPECT_NEAR(c.amplitude / cycle.amplitude, 1.0, 1e-5);
    EXPECT_TRUE(c.stuck());
    // Two stick episodes per cycle, each found to within a step at either end.
    EXPECT_NEAR(c.stick_duration, 2.0 * S, 4.0 * dt + 2e-4) << "stick " << S << " s";
  }
}

}  // namespace
}  // namespace fl
