// The Bullet world against the friction laws' closed forms (docs/friction-laws.md) at the lab's
// default 1 ms step: the stick-slip cycle's period, a slip-dependent law's growth and decay rates,
// and the clipped cycle's amplitude with the half-step lag docs/physics.md derives. The closed
// forms are called here directly (core/), not through the run's own theory numbers.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/friction_oscillator.hpp"
#include "core/stick_slip_cycle.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

// The minimal scene without its sensor: the trajectory is what is compared.
Scene minimal(std::vector<SceneOverride> overrides) {
  return test::minimal_without_sensor(overrides);
}

PlateOnRollers plate_of(const CompiledRig& rig) {
  return {rig.rollers.spacing, rig.plate.h_c, rig.world.gravity};
}

double surface_speed(const Scene& s) {
  return s.rollers.speed * s.rollers.radius;
}

// mu_s from 1.1 to 2.07 mu_k (mu_k = 0.29) at 200 rpm from 30 mm: a stick-slip cycle with sticks
// of 2 x_b / v_r, its period within 1e-4 of the closed form at the scene's 1 ms.
TEST(FrictionLawAccuracy, StickSlipCycleWithinOneTenThousandthOfItsClosedForm) {
  for (const char* mu_s : {"0.319", "0.348", "0.4", "0.5", "0.6"}) {
    const Scene s = minimal({{"rollers.speed", "200 rpm"},
                             {"plate.offset", "30 mm"},
                             {"friction.mu_s", mu_s},
                             {"world.duration", "6 s"}});
    const CompiledRig rig = compile_rig(s);
    const StickSlipCycle cycle = stick_slip_cycle(rig.friction, plate_of(rig), surface_speed(s));
    const RunSummary r = run_experiment(rig, {});
    ASSERT_EQ(r.regime, Regime::kStickSlip) << mu_s << ": " << r.regime_evidence;
    ASSERT_TRUE(r.stick_slip_period && r.stick_slip_amplitude && r.stick_duration) << mu_s;
    EXPECT_NEAR(*r.stick_slip_period / cycle.period, 1.0, 1e-4) << mu_s;
    // The amplitude and the stick's length carry the step in which the stick is found: at most
    // v_r dt of travel, one step of time.
    EXPECT_NEAR(*r.stick_slip_amplitude, cycle.amplitude, surface_speed(s) * s.world.time_step)
        << mu_s;
    EXPECT_NEAR(*r.stick_duration, cycle.stick_duration, 1.5 * s.world.time_step) << mu_s;
  }
}

// The cycle's error is second order in the step: a stick breaks where the ratio |F|/N crosses
// mu_s within the half steps the step's impulse stands for (docs/physics.md). A quarter of the step
// takes the error to a sixteenth (measured: 7.5e-5 at 2 ms, 5.4e-6 at 0.5 ms); first order, which
// breaking half a step late gave, would leave a quarter. Asserted below 0.15 of it, between the
// two.
TEST(FrictionLawAccuracy, StickSlipCycleErrorIsSecondOrderInTheStep) {
  const auto error_at = [](const char* step) {
    const Scene s = minimal({{"rollers.speed", "200 rpm"},
                             {"plate.offset", "30 mm"},
                             {"friction.mu_s", "0.6"},
                             {"world.time_step", step},
                             {"world.duration", "8 s"}});
    const CompiledRig rig = compile_rig(s);
    const StickSlipCycle cycle = stick_slip_cycle(rig.friction, plate_of(rig), surface_speed(s));
    const RunSummary r = run_experiment(rig, {});
    EXPECT_EQ(r.regime, Regime::kStickSlip) << step;
    return std::fabs(r.stick_slip_period.value_or(0.0) / cycle.period - 1.0);
  };
  const double coarse = error_at("2 ms"), fine = error_at("0.5 ms");
  EXPECT_LT(fine, 0.15 * coarse) << coarse << " at 2 ms, " << fine << " at 0.5 ms";
}

// A linear law: x'' - 2 gamma x' + Omega^2 x = 0 exactly while both rollers slip, with
// gamma = -g l beta / (2 (l - 2 mu(v_r) h_c)).
TEST(FrictionLawAccuracy, GrowthAndDecayRatesWithinOneThousandthOfTheLinearisedRate) {
  for (const char* beta : {"-0.01 s/m", "0.02 s/m"}) {
    const Scene s = minimal(
        {{"friction.law", "stribeck"}, {"friction.beta", beta}, {"world.duration", "10 s"}});
    const CompiledRig rig = compile_rig(s);
    const LinearisedMotion motion =
        linearised_motion(rig.friction, plate_of(rig), surface_speed(s));
    const RunSummary r = run_experiment(rig, {});
    ASSERT_EQ(r.regime, motion.gamma > 0.0 ? Regime::kGrows : Regime::kDecays)
        << beta << ": " << r.regime_evidence;
    ASSERT_TRUE(r.growth_rate.has_value());
    EXPECT_NEAR(*r.growth_rate / motion.gamma, 1.0, 1e-3) << beta;
    // The period of a growing or decaying oscillation: 2 pi / sqrt(Omega^2 - gamma^2).
    ASSERT_TRUE(r.period_trajectory.has_value());
    EXPECT_NEAR(*r.period_trajectory / motion.period, 1.0, 1e-4) << beta;
  }
}

// mu_s = mu_k at 200 rpm: one stick clips the amplitude to v_r / Omega, where it stays (the plate
// touching the roller's speed for a step in each cycle) until a graze trims it: the solver finds
// the contact stuck whenever the step's kinetic impulse would carry the plate past v_r, and the
// amplitude drops, in one graze or two, until the cycle's largest speed stays mu_k g dt / 2
// below v_r: it settles at (v_r - mu_k g dt / 2) / Omega, first order in dt (docs/physics.md).
// When the graze comes depends on where the steps fall in the cycle (10.7 s at 1 ms, 2.1 s at
// 0.5 ms on this scene); within 20 s at both.
TEST(FrictionLawAccuracy, ClippedAmplitudeLagsByHalfAStepsKineticSpeedChange) {
  std::vector<double> deficits;
  for (const char* step : {"1 ms", "0.5 ms"}) {
    const Scene s = minimal({{"rollers.speed", "200 rpm"},
                             {"plate.offset", "30 mm"},
                             {"world.time_step", step},
                             {"world.duration", "40 s"}});
    const CompiledRig rig = compile_rig(s);
    const double omega = sliding_angular_frequency(rig.friction, plate_of(rig), surface_speed(s));
    RunOptions options;
    options.record_cycles = true;
    RunRecording recording;
    const RunSummary r = run_experiment(rig, options, &recording);
    ASSERT_EQ(r.regime, Regime::kClipped) << step << ": " << r.regime_evidence;
    ASSERT_TRUE(r.amplitude_clipped.has_value());
    const double predicted =
        rig.friction.mu_k * rig.world.gravity * s.world.time_step / (2.0 * omega);
    const double deficit = surface_speed(s) / omega - *r.amplitude_clipped;
    EXPECT_NEAR(deficit / predicted, 1.0, 0.1) << step;
    deficits.push_back(deficit);
    // The course of the trimming, cycle by cycle: at v_r / Omega (to a micrometre) until the
    // first drop, at most two drops, none larger than the whole deficit, the last within 20 s.
    ASSERT_GE(recording.cycles.size(), 40u);
    constexpr double kMicrometre = 1e-6;
    const double clipped = surface_speed(s) / omega;
    EXPECT_NEAR(recording.cycles.front().amplitude, clipped, kMicrometre) << step;
    int drops = 0;
    double last_drop = 0.0;
    for (std::size_t i = 1; i < recording.cycles.size(); ++i) {
      const double change = recording.cycles[i].amplitude - recording.cycles[i - 1].amplitude;
      EXPECT_LT(change, kMicrometre) << step << " at " << recording.cycles[i].start;
      if (change < -kMicrometre) {
        ++drops;
        last_drop = recording.cycles[i].start;
        EXPECT_LT(-change, predicted + kMicrometre) << step << " at " << last_drop;
      }
    }
    EXPECT_GE(drops, 1) << step;
    EXPECT_LE(drops, 2) << step;
    EXPECT_LT(last_drop, 20.0) << step;
    // The period is the thick formula's: the clip does not change it.
    ASSERT_TRUE(r.period_trajectory.has_value());
    EXPECT_NEAR(*r.period_trajectory / (2.0 * std::acos(-1.0) / omega), 1.0, 1e-4) << step;
  }
  EXPECT_NEAR(deficits[0] / deficits[1], 2.0, 0.2);
}

}  // namespace
}  // namespace fl
