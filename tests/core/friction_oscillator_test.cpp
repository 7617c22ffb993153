// The closed forms of the friction oscillator beyond ideal coulomb (core/friction_oscillator.hpp,
// core/stick_slip_cycle.hpp, core/averaged_motion.hpp) against hand values and against the
// independent reference model (tests/support/reference_oscillator.hpp), each with the tolerance
// of its claim: exact closed forms to the reference's accuracy (1e-6 and tighter), the linearised
// growth rate within 1e-4 where it is exact or its correction is computed to be far smaller, the
// averaged motion within eps^2 (eps = the largest |gamma(A)| / Omega: it is first order, and the
// odd slip force has no second-order amplitude term). And the refusal of meaningless input.
#include "core/friction_oscillator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "core/averaged_motion.hpp"
#include "core/stick_slip_cycle.hpp"
#include "support/reference_oscillator.hpp"

namespace fl {
namespace {

using test::ReferenceOptions;
using test::ReferenceRig;
using test::ReferenceRun;
using test::simulate_reference;

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

FrictionLaw stribeck(double mu_k, double mu_s, double v_s, double beta) {
  FrictionLaw law;
  law.kind = FrictionLawKind::kStribeck;
  law.mu_k = mu_k;
  law.mu_s = mu_s;
  law.v_s = v_s;
  law.beta = beta;
  return law;
}

PlateOnRollers plate_with(double h_c) {
  return PlateOnRollers{kL, h_c, kG};
}

ReferenceRig rig_with(double h_c, double surface_speed) {
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

double relative(double measured, double expected) {
  return measured / expected - 1.0;
}

// The largest |error| passed through it: the "measured" figure docs/friction-laws.md gives.
struct Worst {
  double value = 0.0;
  double operator()(double error) {
    value = std::max(value, std::abs(error));
    return error;
  }
};

// ---- effective coefficient, frequency, stick ---------------------------------------------------

TEST(FrictionOscillator, CoulombFrequencyIsTheThickPlatesAtAnyRollerSpeed) {
  for (double v_r : {0.05, kSlow, kFast}) {
    EXPECT_EQ(effective_mu(coulomb(0.29, 0.4), v_r), 0.29);
    EXPECT_NEAR(sliding_angular_frequency(coulomb(0.29, 0.4), plate_with(0.0025), v_r),
                angular_frequency(kL, 0.29, 0.0025, kG), 1e-12);
  }
}

TEST(FrictionOscillator, StribeckEffectiveMuIsTheLawAtTheRollersSpeed) {
  // mu(v_r) = 0.29 + 0.145 exp(-(0.2094 / 0.1)^2) + 0.05 * 0.2094, by hand (python).
  const FrictionLaw law = stribeck(0.29, 0.435, 0.1, 0.05);
  EXPECT_NEAR(effective_mu(law, kSlow), 0.3022774151712615, 1e-15);
  EXPECT_NEAR(sliding_angular_frequency(law, plate_with(0.0025), kSlow),
              angular_frequency(kL, 0.3022774151712615, 0.0025, kG), 1e-12);
}

TEST(FrictionOscillator, StickBreakOffsetByHandAndIndependentOfHc) {
  // (l/2) (mu_s - mu_k) / (mu_s + mu_k) = 0.0445 * 0.11 / 0.69 for coulomb 0.29 / 0.4.
  for (double h_c : {0.0, 0.0025, 0.02}) {
    EXPECT_NEAR(stick_break_offset(coulomb(0.29, 0.4), plate_with(h_c), kSlow),
                0.0445 * 0.11 / 0.69, 1e-16);
  }
  EXPECT_EQ(stick_break_offset(coulomb(0.29, 0.29), plate_with(0.0025), kSlow), 0.0);
  // A law rising above mu_s at 2 v_r breaks before the centre: x_b < 0.
  EXPECT_LT(stick_break_offset(stribeck(0.29, 0.29, 0.01, 0.5), plate_with(0.0), kSlow), 0.0);
}

TEST(FrictionOscillator, StickHoldsUpToTheBreakOffsetOnEitherRoller) {
  const FrictionLaw law = stribeck(0.29, 0.4, 0.05, 0.1);
  const double x_b = stick_break_offset(law, plate_with(0.0025), 0.1);
  EXPECT_TRUE(stick_holds(law, plate_with(0.0025), 0.1, 0, x_b - 1e-9));
  EXPECT_FALSE(stick_holds(law, plate_with(0.0025), 0.1, 0, x_b + 1e-9));
  EXPECT_TRUE(stick_holds(law, plate_with(0.0025), 0.1, 1, -x_b + 1e-9));
  EXPECT_FALSE(stick_holds(law, plate_with(0.0025), 0.1, 1, -x_b - 1e-9));
  EXPECT_TRUE(stick_holds(law, plate_with(0.0025), 0.1, 0, -0.04));
  EXPECT_FALSE(stick_holds(law, plate_with(0.0025), 0.1, 1, -0.04));
}

TEST(FrictionOscillator, StickBreaksWhereTheReferenceModelBreaksIt) {
  // A stribeck law (no closed-form cycle) and h_c up to 20 mm: every stick the reference model
  // ends, it ends at +-x_b. The reference places the end by bisection to double precision.
  const FrictionLaw law = stribeck(0.29, 0.4, 0.05, 0.1);
  Worst worst;
  for (double h_c : {0.0, 0.0025, 0.02}) {
    const double x_b = stick_break_offset(law, plate_with(h_c), 0.1);
    const ReferenceRun run =
        simulate_reference(law, rig_with(h_c, 0.1), -0.03, 0.0, for_seconds(3));
    const auto sticks = test::stick_intervals(run);
    ASSERT_GE(sticks.size(), 6u) << h_c;
    for (const auto& s : sticks) {
      if (s.end >= run.end_time) continue;
      EXPECT_NEAR(worst(s.x_end - (s.roller == 0 ? x_b : -x_b)), 0.0, 1e-12)
          << h_c << " " << s.start;
    }
  }
  std::printf("measured: stick break %.2g m off\n", worst.value);
}

// ---- full slip
// ------------------------------------------------------------------------------------

TEST(FrictionOscillator, FullSlipSpeedForCoulombIsAOmegaWhateverMuS) {
  const double omega = angular_frequency(kL, 0.29, 0.0025, kG);
  for (double mu_s : {0.29, 0.35, 0.5}) {
    const double v = full_slip_surface_speed(coulomb(0.29, mu_s), plate_with(0.0025), 0.03);
    EXPECT_NEAR(relative(v, 0.03 * omega), 0.0, 1e-14);
    EXPECT_NEAR(full_slip_roller_speed(coulomb(0.29, mu_s), plate_with(0.0025), 0.03, 0.01),
                0.03 * omega / 0.01, 1e-10);
  }
  // The existing ideal-coulomb formula agrees.
  EXPECT_NEAR(full_slip_surface_speed(coulomb(0.29, 0.29), plate_with(0.0025), 0.03) / 0.01,
              roller_speed_for_full_slip(0.03, 0.01, kL, 0.29, 0.0025, kG), 1e-10);
}

TEST(FrictionOscillator, AFallingLawLowersTheThresholdARisingOneRaisesIt) {
  // docs/friction-laws.md: at the rig's 30 mm (10 mm rollers, h_c 2.5 mm), 231 rpm for Coulomb,
  // 226 rpm for beta = -0.05 s/m and 236 rpm for +0.05 s/m. Independently: a linear law's mu at
  // v_r is mu_k + beta v_r, so the root satisfies v = A Omega(mu_k + beta v) by fixed point.
  constexpr double kRpm = 2.0 * kPi / 60.0;
  const PlateOnRollers plate = plate_with(0.0025);
  for (const auto& [beta, rpm] : {std::pair{-0.05, 226.0}, {0.0, 231.0}, {0.05, 236.0}}) {
    double v = 0.03 * angular_frequency(kL, 0.29, 0.0025, kG);
    for (int i = 0; i < 100; ++i) v = 0.03 * angular_frequency(kL, 0.29 + beta * v, 0.0025, kG);
    const double speed =
        full_slip_roller_speed(stribeck(0.29, 0.29, 0.01, beta), plate, 0.03, 0.01);
    EXPECT_NEAR(speed, v / 0.01, 1e-9 * speed) << beta;
    EXPECT_NEAR(speed / kRpm, rpm, 0.5) << beta;
  }
}

TEST(FrictionOscillator, FullSlipSpeedSolvesVEqualsAOmegaOfMuOfV) {
  for (const FrictionLaw& law :
       {stribeck(0.29, 0.29, 0.01, 0.3), stribeck(0.29, 0.29, 0.01, -0.2),
        stribeck(0.29, 0.435, 0.1, 0.0), stribeck(0.29, 0.435, 0.001, 0.05)}) {
    const double v = full_slip_surface_speed(law, plate_with(0.0025), 0.03);
    EXPECT_NEAR(relative(v, 0.03 * sliding_angular_frequency(law, plate_with(0.0025), v)), 0.0,
                1e-12);
    EXPECT_NEAR(full_slip_margin(law, plate_with(0.0025), v, 0.03), 1.0, 1e-12);
  }
}

TEST(FrictionOscillator, AboveTheFullSlipSpeedCoulombNeverSticksBelowItSticks) {
  // The reference model at 0.1 % either side, with a large mu_s (it does not matter).
  const FrictionLaw law = coulomb(0.29, 0.5);
  const double v = full_slip_surface_speed(law, plate_with(0.0025), 0.03);
  const ReferenceRun above =
      simulate_reference(law, rig_with(0.0025, 1.001 * v), 0.03, 0.0, for_seconds(5));
  EXPECT_TRUE(test::stick_intervals(above).empty());
  const ReferenceRun below =
      simulate_reference(law, rig_with(0.0025, 0.999 * v), 0.03, 0.0, for_seconds(5));
  EXPECT_FALSE(test::stick_intervals(below).empty());
}

// ---- the coulomb stick-slip and clipped cycles
// ---------------------------------------------------

TEST(StickSlipCycle, ByHandForTheRigAt200Rpm) {
  // mu_s / mu_k = 1.5 at h_c = 2.5 mm: x_b = 0.0445 * 0.5 / 2.5 = 8.9 mm; python, 17 digits.
  const StickSlipCycle c = stick_slip_cycle(coulomb(0.29, 0.435), plate_with(0.0025), kSlow);
  const double omega = angular_frequency(kL, 0.29, 0.0025, kG);
  EXPECT_NEAR(c.break_offset, 0.0089, 1e-16);
  EXPECT_NEAR(c.amplitude, std::hypot(0.0089, kSlow / omega), 1e-16);
  EXPECT_NEAR(c.stick_duration, 2.0 * 0.0089 / kSlow, 1e-16);
  EXPECT_NEAR(c.slip_duration, 2.0 / omega * std::atan(kSlow / (omega * 0.0089)), 1e-15);
  EXPECT_NEAR(c.period, 2.0 * (c.stick_duration + c.slip_duration), 1e-15);
  EXPECT_FALSE(c.clipped);
}

TEST(StickSlipCycle, MatchesTheReferenceModelToOnePartInAMillion) {
  // The claim of the closed form: period, amplitude and stick duration within 1e-6 relative.
  Worst period, amplitude, duration;
  for (double ratio : {1.1, 1.3, 1.5}) {
    for (double h_c : {0.0025, 0.0036}) {
      const FrictionLaw law = coulomb(0.29, 0.29 * ratio);
      const StickSlipCycle c = stick_slip_cycle(law, plate_with(h_c), kSlow);
      const ReferenceRun run =
          simulate_reference(law, rig_with(h_c, kSlow), 0.03, 0.0, for_seconds(12));
      ASSERT_FALSE(run.tipped);
      EXPECT_NEAR(period(relative(test::period_from_up_crossings(run, 2.0), c.period)), 0.0, 1e-6)
          << ratio << " " << h_c;
      for (const auto& p : test::turning_points(run, 2.0))
        EXPECT_NEAR(amplitude(relative(std::abs(p.x), c.amplitude)), 0.0, 1e-6) << p.t;
      const auto sticks = test::stick_intervals(run);
      ASSERT_GE(sticks.size(), 20u);
      for (std::size_t i = 1; i + 1 < sticks.size(); ++i) {
        EXPECT_NEAR(duration(relative(sticks[i].end - sticks[i].start, c.stick_duration)), 0.0,
                    1e-6);
        EXPECT_NEAR(std::abs(sticks[i].x_start), c.break_offset, 1e-9);
      }
    }
  }
  std::printf("measured: period %.2g, amplitude %.2g, stick duration %.2g off\n", period.value,
              amplitude.value, duration.value);
}

TEST(StickSlipCycle, ClippedCycleForEqualStaticAndKineticMu) {
  // mu_s = mu_k: one stick clips the amplitude to v_r / Omega; then the period is 2 pi / Omega.
  const FrictionLaw law = coulomb(0.29, 0.29);
  const StickSlipCycle c = stick_slip_cycle(law, plate_with(0.0025), kSlow);
  const double omega = angular_frequency(kL, 0.29, 0.0025, kG);
  EXPECT_TRUE(c.clipped);
  EXPECT_EQ(c.stick_duration, 0.0);
  EXPECT_NEAR(c.amplitude, kSlow / omega, 1e-16);
  EXPECT_NEAR(c.period, 2.0 * kPi / omega, 1e-15);
  const ReferenceRun run =
      simulate_reference(law, rig_with(0.0025, kSlow), 0.03, 0.0, for_seconds(12));
  const auto sticks = test::stick_intervals(run);
  ASSERT_FALSE(sticks.empty());
  // The first stick is a real one (from x_e < 0 to 0); any later one is a graze of zero length.
  EXPECT_GT(sticks.front().end - sticks.front().start, 0.05);
  for (std::size_t i = 1; i < sticks.size(); ++i) EXPECT_LT(sticks[i].end - sticks[i].start, 1e-9);
  Worst period, amplitude;
  EXPECT_NEAR(period(relative(test::period_from_up_crossings(run, 1.0), c.period)), 0.0, 1e-6);
  for (const auto& p : test::turning_points(run, 1.0))
    EXPECT_NEAR(amplitude(relative(std::abs(p.x), c.amplitude)), 0.0, 1e-6) << p.t;
  std::printf("measured: amplitude %.2g, period %.2g off\n", amplitude.value, period.value);
}

TEST(StickSlipCycle, FirstStickMatchesTheReferenceModel) {
  Worst worst;
  for (double ratio : {1.0, 1.5}) {
    const FrictionLaw law = coulomb(0.29, 0.29 * ratio);
    const FirstStick f = first_stick(law, plate_with(0.0025), kSlow, 0.03);
    const ReferenceRun run =
        simulate_reference(law, rig_with(0.0025, kSlow), -0.03, 0.0, for_seconds(1));
    const auto sticks = test::stick_intervals(run);
    ASSERT_FALSE(sticks.empty());
    EXPECT_EQ(sticks.front().roller, 0);
    EXPECT_NEAR(worst(relative(sticks.front().start, f.time_to_stick)), 0.0, 1e-9);
    EXPECT_NEAR(worst(relative(sticks.front().x_start, f.entry_offset)), 0.0, 1e-9);
    EXPECT_NEAR(worst(relative(sticks.front().end - sticks.front().start, f.duration)), 0.0, 1e-9);
  }
  std::printf("measured: first stick %.2g off\n", worst.value);
}

// ---- growth rate: linearised and averaged ----------------------------------------------------

TEST(GrowthRate, LinearisedRateByHand) {
  // gamma = -g l mu' / (2 (l - 2 mu h_c)) for the linear law mu = 0.29 + beta s at v_r.
  const FrictionLaw law = stribeck(0.29, 0.29, 0.01, 0.1);
  const LinearisedMotion m = linearised_motion(law, plate_with(0.0025), kFast);
  const double mu = 0.29 + 0.1 * kFast;
  EXPECT_NEAR(m.mu, mu, 1e-15);
  EXPECT_NEAR(m.slope, 0.1, 1e-15);
  const double gamma = -kG * kL * 0.1 / (2.0 * (kL - 2.0 * mu * 0.0025));
  EXPECT_NEAR(m.gamma, gamma, 1e-14);
  // The damped oscillator's period from the hand-written Omega and gamma, not the result's own:
  // Omega^2 = 2 mu g / (l - 2 mu h_c), T = 2 pi / sqrt(Omega^2 - gamma^2).
  const double omega2 = 2.0 * mu * kG / (kL - 2.0 * mu * 0.0025);
  EXPECT_NEAR(m.omega, std::sqrt(omega2), 1e-13);
  EXPECT_NEAR(m.period, 2.0 * kPi / std::sqrt(omega2 - gamma * gamma), 1e-13);
  EXPECT_NEAR(m.period_0, period_thick(kL, mu, 0.0025, kG), 1e-14);
}

TEST(GrowthRate, LinearLawMatchesTheReferenceModel) {
  // A linear law makes the slipping plate an exact damped oscillator: gamma within 1e-4 (the
  // claim), the period 2 pi / sqrt(Omega^2 - gamma^2) within 1e-9, and the change from the
  // coulomb period at mu(v_r) is second order: (gamma / Omega)^2 / 2.
  Worst gamma, period_error;
  for (double beta : {-0.01, -0.001, 0.001, 0.01}) {
    const FrictionLaw law = stribeck(0.29, 0.29, 0.01, beta);
    const LinearisedMotion m = linearised_motion(law, plate_with(0.0025), kFast);
    const ReferenceRun run =
        simulate_reference(law, rig_with(0.0025, kFast), 0.02, 0.0, for_seconds(20));
    ASSERT_TRUE(test::stick_intervals(run).empty());
    EXPECT_NEAR(gamma(relative(test::amplitude_growth_rate(run), m.gamma)), 0.0, 1e-4) << beta;
    EXPECT_EQ(m.gamma > 0.0, beta < 0.0);
    const double period = test::period_from_up_crossings(run);
    EXPECT_NEAR(period_error(relative(period, m.period)), 0.0, 1e-9) << beta;
    const double second_order = 0.5 * std::pow(m.gamma / m.omega, 2);
    EXPECT_NEAR(relative(period, m.period_0), second_order, 0.01 * second_order) << beta;
  }
  std::printf("measured: gamma %.2g, period %.2g off\n", gamma.value, period_error.value);
}

TEST(GrowthRate, StribeckLinearisedRateIsTheSmallAmplitudeLimit) {
  // A stribeck law at 200 rpm (mu falls at v_r: the amplitude grows). Started at 20 um it stays
  // below 60 um for 2.5 s, where the averaged rate differs from the linearised one by less than
  // 2e-5: the linearised rate must then hold within 1e-4.
  const FrictionLaw law = stribeck(0.29, 0.4, 0.1, 0.0);
  const LinearisedMotion m = linearised_motion(law, plate_with(0.0025), kSlow);
  ASSERT_GT(m.gamma, 0.0);
  const ReferenceRun run =
      simulate_reference(law, rig_with(0.0025, kSlow), 2e-5, 0.0, for_seconds(2.5));
  double largest = 0.0;
  for (const auto& p : test::turning_points(run)) largest = std::max(largest, std::abs(p.x));
  ASSERT_LT(largest, 6e-5);
  ASSERT_LT(
      std::abs(relative(averaged_growth_rate(law, plate_with(0.0025), kSlow, largest), m.gamma)),
      2e-5);
  const double gamma_error = relative(test::amplitude_growth_rate(run), m.gamma);
  EXPECT_NEAR(gamma_error, 0.0, 1e-4);
  EXPECT_NEAR(relative(test::period_from_up_crossings(run), m.period), 0.0, 1e-6);
  std::printf("measured: gamma %.2g off\n", std::abs(gamma_error));
}

TEST(GrowthRate, AveragedRateReducesToTheLinearisedOne) {
  // Exactly for a linear law at any amplitude; in the limit A -> 0 for any law.
  const FrictionLaw linear = stribeck(0.29, 0.29, 0.01, 0.05);
  const LinearisedMotion lin = linearised_motion(linear, plate_with(0.0025), kSlow);
  const double reach = kSlow / lin.omega;
  for (double f : {0.01, 0.5, 1.0}) {
    EXPECT_NEAR(
        relative(averaged_growth_rate(linear, plate_with(0.0025), kSlow, f * reach), lin.gamma),
        0.0, 1e-12);
    EXPECT_NEAR(relative(averaged_period(linear, plate_with(0.0025), kSlow, f * reach), lin.period),
                0.0, 1e-12);
  }
  const FrictionLaw law = stribeck(0.29, 0.4, 0.1, 0.02);
  const LinearisedMotion m = linearised_motion(law, plate_with(0.0025), kSlow);
  EXPECT_NEAR(relative(averaged_growth_rate(law, plate_with(0.0025), kSlow, 1e-7), m.gamma), 0.0,
              1e-9);
  EXPECT_NEAR(relative(averaged_period(law, plate_with(0.0025), kSlow, 1e-7), m.period), 0.0, 1e-9);
  // Coulomb: no slip force, no gain on the arc between sticks.
  EXPECT_EQ(averaged_growth_rate(coulomb(0.29, 0.4), plate_with(0.0025), kSlow, 0.01), 0.0);
  EXPECT_EQ(slip_arc_energy_gain(coulomb(0.29, 0.4), plate_with(0.0025), kSlow), 0.0);
}

TEST(GrowthRate, AveragedMotionPredictsTheSlipLimitCycle) {
  // mu falls at v_r (small oscillations grow) but rises on average over a wide cycle (large ones
  // decay): a stable slip cycle where gamma(A) = 0, which the reference model reaches from below
  // and from above. Its amplitude and period within eps^2, eps = max |gamma(A)| / Omega.
  const FrictionLaw law = stribeck(0.29, 0.319, 0.1, 0.24);
  const double v_r = 0.0707;
  const PlateOnRollers plate = plate_with(0.0025);
  const double omega = sliding_angular_frequency(law, plate, v_r);
  const double reach = v_r / omega;
  double eps = 0.0;
  for (int i = 1; i <= 100; ++i)
    eps = std::max(eps, std::abs(averaged_growth_rate(law, plate, v_r, i * reach / 100)) / omega);
  ASSERT_LT(eps, 0.05);
  // The root of gamma(A) by bisection.
  double lo = 0.1 * reach;
  double hi = 0.9 * reach;
  ASSERT_GT(averaged_growth_rate(law, plate, v_r, lo), 0.0);
  ASSERT_LT(averaged_growth_rate(law, plate, v_r, hi), 0.0);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (averaged_growth_rate(law, plate, v_r, mid) > 0.0 ? lo : hi) = mid;
  }
  const double settled = 0.5 * (lo + hi);
  EXPECT_NEAR(settled, 3.135e-3, 0.5e-6) << "docs/friction-laws.md's 3.135 mm";
  const double period = averaged_period(law, plate, v_r, settled);
  Worst amplitude, period_error;
  for (double start : {0.3 * reach, 0.9 * reach}) {
    const ReferenceRun run =
        simulate_reference(law, rig_with(0.0025, v_r), start, 0.0, for_seconds(200));
    ASSERT_TRUE(test::stick_intervals(run).empty());
    for (const auto& p : test::turning_points(run, 150.0))
      EXPECT_NEAR(amplitude(relative(std::abs(p.x), settled)), 0.0, eps * eps) << start;
    EXPECT_NEAR(period_error(relative(test::period_from_up_crossings(run, 150.0), period)), 0.0,
                eps * eps);
  }
  std::printf("measured: eps %.2g; amplitude %.2g, period %.2g off\n", eps, amplitude.value,
              period_error.value);
}

// ---- refusals
// ---------------------------------------------------------------------------------------

TEST(FrictionOscillator, RefusesMeaninglessInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const FrictionLaw good = coulomb(0.29, 0.4);
  const PlateOnRollers plate = plate_with(0.0025);
  // The law.
  EXPECT_THROW(check_friction_law(coulomb(0.0, 0.4), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(coulomb(0.29, 0.2), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(coulomb(nan, 0.4), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(coulomb(0.29, inf), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(stribeck(0.29, 0.4, 0.0, 0.0), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(stribeck(0.29, 0.4, 0.01, nan), 1.0), DomainError);
  EXPECT_THROW(check_friction_law(stribeck(0.29, 0.29, 0.01, -0.5), 1.0), DomainError);
  EXPECT_NO_THROW(check_friction_law(stribeck(0.29, 0.29, 0.01, -0.5), 0.5));
  EXPECT_THROW(check_friction_law(good, -1.0), DomainError);
  // The plate and the speeds.
  EXPECT_THROW(effective_mu(good, 0.0), DomainError);
  EXPECT_THROW(effective_mu(good, -kSlow), DomainError);
  EXPECT_THROW(effective_mu(good, nan), DomainError);
  EXPECT_THROW(sliding_angular_frequency(good, PlateOnRollers{0.0, 0.0, kG}, kSlow), DomainError);
  EXPECT_THROW(sliding_angular_frequency(good, PlateOnRollers{kL, -0.001, kG}, kSlow), DomainError);
  EXPECT_THROW(sliding_angular_frequency(good, PlateOnRollers{kL, 0.0, 0.0}, kSlow), DomainError);
  // Falling law below zero at 2 v_r (beta = -0.5 s/m at 1600 rpm).
  EXPECT_THROW(effective_mu(stribeck(0.29, 0.29, 0.01, -0.5), kFast), DomainError);
  // No restoring force: l <= 2 mu h_c.
  EXPECT_THROW(sliding_angular_frequency(coulomb(10.0, 10.0), plate_with(0.005), kSlow),
               DomainError);
  // Stick.
  EXPECT_THROW(stick_holds(good, plate, kSlow, 2, 0.0), DomainError);
  EXPECT_THROW(stick_holds(good, plate, kSlow, 0, 0.0445), DomainError);
  EXPECT_THROW(stick_holds(good, plate, kSlow, 0, nan), DomainError);
  // Full slip.
  EXPECT_THROW(full_slip_surface_speed(good, plate, 0.0), DomainError);
  EXPECT_THROW(full_slip_surface_speed(good, plate, nan), DomainError);
  EXPECT_THROW(full_slip_roller_speed(good, plate, 0.03, 0.0), DomainError);
  EXPECT_THROW(full_slip_margin(good, plate, kSlow, -0.03), DomainError);
  // A falling law that stops meaning anything before the plate's speed is reached.
  EXPECT_THROW(full_slip_surface_speed(stribeck(0.29, 0.29, 0.01, -2.0), plate, 0.03), DomainError);
  // Linearised motion with |gamma| >= Omega: beta = 10 s/m.
  EXPECT_THROW(linearised_motion(stribeck(0.29, 0.29, 0.01, 10.0), plate, kSlow), DomainError);
  // Cycles: slip-dependent law, tipping, never sticking.
  EXPECT_THROW(stick_slip_cycle(stribeck(0.29, 0.4, 0.01, 0.0), plate, kSlow), DomainError);
  EXPECT_THROW(stick_slip_cycle(coulomb(0.29, 0.4), plate, 2.0), DomainError);
  EXPECT_THROW(first_stick(good, plate, kFast, 0.03), DomainError);
  EXPECT_THROW(first_stick(good, plate, kSlow, 0.05), DomainError);
  EXPECT_THROW(first_stick(stribeck(0.29, 0.29, 0.01, 0.1), plate, kSlow, 0.03), DomainError);
  // Averaged motion beyond the roller's speed, and the arc without a positive break offset.
  EXPECT_THROW(averaged_growth_rate(good, plate, kSlow, 0.03), DomainError);
  EXPECT_THROW(averaged_growth_rate(good, plate, kSlow, 0.0), DomainError);
  EXPECT_THROW(averaged_period(good, plate, kSlow, nan), DomainError);
  EXPECT_THROW(slip_arc_energy_gain(coulomb(0.29, 0.29), plate, kSlow), DomainError);
}

TEST(FrictionOscillator, NeverReturnsANaN) {
  // Every function over a grid that includes edge values returns a finite number or refuses.
  std::vector<FrictionLaw> laws = {coulomb(0.29, 0.29), coulomb(0.29, 1.0), coulomb(5.0, 5.0)};
  for (double beta : {-0.5, 0.0, 0.5})
    for (double v_s : {1e-4, 0.01, 10.0}) laws.push_back(stribeck(0.29, 0.6, v_s, beta));
  int finite = 0;
  for (const FrictionLaw& law : laws) {
    for (double h_c : {0.0, 0.0025, 0.0089}) {
      for (double v_r : {1e-9, kSlow, kFast, 100.0}) {
        for (double amplitude : {1e-9, 0.03, 0.04}) {
          const PlateOnRollers plate = plate_with(h_c);
          const auto check = [&](auto f) {
            try {
              const double value = f();
              EXPECT_TRUE(std::isfinite(value)) << value;
              ++finite;
            } catch (const DomainError&) {
            }
          };
          check([&] { return sliding_angular_frequency(law, plate, v_r); });
          check([&] { return stick_break_offset(law, plate, v_r); });
          check([&] { return full_slip_margin(law, plate, v_r, amplitude); });
          check([&] { return linearised_motion(law, plate, v_r).period; });
          check([&] { return linearised_motion(law, plate, v_r).gamma; });
          check([&] { return stick_slip_cycle(law, plate, v_r).period; });
          check([&] { return first_stick(law, plate, v_r, amplitude).duration; });
          check([&] { return averaged_growth_rate(law, plate, v_r, amplitude); });
          check([&] { return averaged_period(law, plate, v_r, amplitude); });
          check([&] { return slip_arc_energy_gain(law, plate, v_r); });
        }
      }
      try {
        EXPECT_TRUE(std::isfinite(full_slip_surface_speed(law, plate_with(h_c), 0.03)));
      } catch (const DomainError&) {
      }
    }
  }
  EXPECT_GT(finite, 500);
}

}  // namespace
}  // namespace fl
