// The reference model on its own: with ideal coulomb friction it must be the thick-plate
// harmonic oscillator to the accuracy of its integrator (period to 1e-9, amplitude and energy
// constant), hold a stick exactly at the roller's speed, tip where a normal force vanishes, and
// refuse what it cannot integrate. The closed forms it checks are tested in
// tests/core/friction_oscillator_test.cpp.
#include "support/reference_oscillator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"

namespace fl::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kL = 0.089;
constexpr double kG = 9.81;
constexpr double kFast = 1.676;   // 1600 rpm on 10 mm rollers [m/s]
constexpr double kSlow = 0.2094;  // 200 rpm

FrictionLaw coulomb(double mu_k, double mu_s) {
  FrictionLaw law;
  law.mu_k = mu_k;
  law.mu_s = mu_s;
  return law;
}

ReferenceRig rig_at(double h_c, double surface_speed) {
  ReferenceRig rig;
  rig.spacing = kL;
  rig.h_c = h_c;
  rig.surface_speed = surface_speed;
  rig.gravity = kG;
  return rig;
}

ReferenceOptions for_seconds(double duration) {
  ReferenceOptions options;
  options.duration = duration;
  return options;
}

TEST(ReferenceOscillator, CoulombGivesTheThickPlatePeriodAndAConstantAmplitude) {
  // Both rollers slip throughout (A Omega < v_r): x'' = -Omega^2 x with the thick-plate Omega.
  // The claim is the integrator's: 1e-9 on the period, and the amplitude constant to 1e-9.
  double worst_period = 0.0, worst_amplitude = 0.0;  // docs/friction-laws.md's "measured"
  for (double mu : {0.29, 1.0}) {
    for (double h_c : {0.0, 0.0025, 0.008}) {
      const double amplitude = 0.02;
      const ReferenceRun run =
          simulate_reference(coulomb(mu, mu), rig_at(h_c, kFast), amplitude, 0.0, for_seconds(20));
      ASSERT_FALSE(run.tipped);
      EXPECT_TRUE(stick_intervals(run).empty());
      const double expected = period_thick(kL, mu, h_c, kG);
      const double period_error = period_from_up_crossings(run) / expected - 1.0;
      EXPECT_NEAR(period_error, 0.0, 1e-9) << mu << " " << h_c;
      worst_period = std::max(worst_period, std::abs(period_error));
      const auto turns = turning_points(run);
      ASSERT_GE(turns.size(), 40u);
      for (const TurningPoint& p : turns) {
        EXPECT_NEAR(std::abs(p.x) / amplitude - 1.0, 0.0, 1e-9) << p.t;
        worst_amplitude = std::max(worst_amplitude, std::abs(std::abs(p.x) / amplitude - 1.0));
      }
      EXPECT_NEAR(amplitude_growth_rate(run), 0.0, 1e-9);
    }
  }
  std::printf("measured: period %.2g, amplitude %.2g off\n", worst_period, worst_amplitude);
}

TEST(ReferenceOscillator, CoulombConservesTheOscillatorEnergyAtEverySample) {
  const double omega = 2.0 * kPi / period_thick(kL, 0.29, 0.0025, kG);
  const ReferenceRun run =
      simulate_reference(coulomb(0.29, 0.29), rig_at(0.0025, kFast), 0.0, 0.15, for_seconds(10));
  const double e0 = 0.5 * 0.15 * 0.15;
  ASSERT_GT(run.samples.size(), 9000u);
  double worst = 0.0;
  for (const ReferenceSample& s : run.samples) {
    const double error = (0.5 * s.v * s.v + 0.5 * omega * omega * s.x * s.x) / e0 - 1.0;
    EXPECT_NEAR(error, 0.0, 1e-9) << s.t;
    worst = std::max(worst, std::abs(error));
  }
  std::printf("measured: energy %.2g off\n", worst);
}

TEST(ReferenceOscillator, AStickHoldsExactlyAtTheRollersSpeed) {
  // mu_s > mu_k at 200 rpm: the plate sticks; while stuck its speed is the roller's, exactly, and
  // it moves in a straight line.
  const ReferenceRun run =
      simulate_reference(coulomb(0.29, 0.4), rig_at(0.0025, kSlow), 0.03, 0.0, for_seconds(5));
  const auto sticks = stick_intervals(run);
  ASSERT_GE(sticks.size(), 6u);
  int stuck_samples = 0;
  for (const ReferenceSample& s : run.samples) {
    if (s.stuck == kNoRoller) continue;
    ++stuck_samples;
    EXPECT_EQ(s.v, s.stuck == 0 ? kSlow : -kSlow) << s.t;
  }
  EXPECT_GT(stuck_samples, 500);
  // Sticks alternate between the rollers, each carrying the plate toward the other.
  for (std::size_t i = 0; i + 1 < sticks.size(); ++i) {
    EXPECT_NE(sticks[i].roller, sticks[i + 1].roller);
    const double w = sticks[i].roller == 0 ? kSlow : -kSlow;
    EXPECT_NEAR(sticks[i].x_end - sticks[i].x_start, w * (sticks[i].end - sticks[i].start), 1e-15);
  }
}

TEST(ReferenceOscillator, EventsAreInTimeOrderAndMirrorUnderXToMinusX) {
  const FrictionLaw law = coulomb(0.29, 0.35);
  const ReferenceRun a = simulate_reference(law, rig_at(0.0025, kSlow), 0.028, 0.0, for_seconds(4));
  const ReferenceRun b =
      simulate_reference(law, rig_at(0.0025, kSlow), -0.028, 0.0, for_seconds(4));
  for (std::size_t i = 0; i + 1 < a.events.size(); ++i) EXPECT_LE(a.events[i].t, a.events[i + 1].t);
  const auto sa = stick_intervals(a);
  const auto sb = stick_intervals(b);
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t i = 0; i < sa.size(); ++i) {
    EXPECT_EQ(sa[i].roller, 1 - sb[i].roller);
    EXPECT_NEAR(sa[i].start, sb[i].start, 1e-12);
    EXPECT_NEAR(sa[i].x_end, -sb[i].x_end, 1e-15);
  }
}

TEST(ReferenceOscillator, TipsWhereTheFarNormalForceVanishes) {
  // Sliding under coulomb friction, N_0 = m g (1/2 - x / (l - 2 mu h_c)) vanishes at
  // x = l/2 - mu h_c whatever the speed.
  const double mu = 0.29;
  const double h_c = 0.0036;
  const double tipping = tipping_amplitude(kL, mu, h_c);
  const double omega = 2.0 * kPi / period_thick(kL, mu, h_c, kG);
  const ReferenceRun run = simulate_reference(coulomb(mu, mu), rig_at(h_c, kFast), 0.0,
                                              omega * (tipping + 0.002), for_seconds(2));
  ASSERT_TRUE(run.tipped);
  ASSERT_FALSE(run.events.empty());
  const ReferenceEvent& tip = run.events.back();
  EXPECT_EQ(tip.kind, ReferenceEventKind::kTip);
  EXPECT_EQ(tip.roller, 0);
  EXPECT_NEAR(tip.x, tipping, 1e-12);
  EXPECT_LT(run.end_time, 0.25 * period_thick(kL, mu, h_c, kG));
}

TEST(ReferenceOscillator, StartingAtARollersSpeedStartsStuckIfTheLimitAllows) {
  const ReferenceRun run =
      simulate_reference(coulomb(0.29, 0.4), rig_at(0.0, kSlow), -0.01, kSlow, for_seconds(0.5));
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(run.events.front().kind, ReferenceEventKind::kStickStart);
  EXPECT_EQ(run.events.front().t, 0.0);
  EXPECT_EQ(run.samples.front().stuck, 0);
}

TEST(ReferenceOscillator, MeasurementsNeedEnoughEvents) {
  const ReferenceRun run =
      simulate_reference(coulomb(0.29, 0.29), rig_at(0.0, kFast), 0.02, 0.0, for_seconds(0.5));
  EXPECT_THROW(period_from_up_crossings(run), std::runtime_error);
  EXPECT_THROW(amplitude_growth_rate(run, 0.3), std::runtime_error);
}

TEST(ReferenceOscillator, RefusesWhatItCannotIntegrate) {
  const FrictionLaw law = coulomb(0.29, 0.29);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(simulate_reference(law, rig_at(0.0, kFast), 0.0445, 0.0), DomainError);
  EXPECT_THROW(simulate_reference(law, rig_at(0.0, kFast), nan, 0.0), DomainError);
  EXPECT_THROW(simulate_reference(law, rig_at(0.0, 0.0), 0.01, 0.0), DomainError);
  EXPECT_THROW(simulate_reference(law, rig_at(-0.001, kFast), 0.01, 0.0), DomainError);
  EXPECT_THROW(simulate_reference(coulomb(0.29, 0.2), rig_at(0.0, kFast), 0.01, 0.0), DomainError);
  ReferenceOptions no_time;
  no_time.duration = 0.0;
  EXPECT_THROW(simulate_reference(law, rig_at(0.0, kFast), 0.01, 0.0, no_time), DomainError);
  FrictionLaw stribeck;
  stribeck.kind = FrictionLawKind::kStribeck;
  stribeck.v_s = 0.0;
  EXPECT_THROW(simulate_reference(stribeck, rig_at(0.0, kFast), 0.01, 0.0), DomainError);
  // A falling linear law that reaches zero at a slip speed the run reaches.
  stribeck.v_s = 0.01;
  stribeck.beta = -0.5;
  EXPECT_THROW(simulate_reference(stribeck, rig_at(0.0, kFast), 0.01, 0.0), DomainError);
  // No restoring force: l <= 2 mu h_c makes the contact problem inconsistent.
  EXPECT_THROW(simulate_reference(coulomb(10.0, 10.0), rig_at(0.005, kFast), 0.01, 0.0),
               DomainError);
}

}  // namespace
}  // namespace fl::test
