// scenes/roller-ramp.yaml (2000 rpm down to 50 rpm and back up over 660 s), the run that
// docs/researchers.md describes, under two laws and against theory:
//  - ideal coulomb (mu_s = mu_k): the start amplitude A0 above the slip threshold A0 Omega / a;
//    the first stick where the ramp crosses it; below, the amplitude clipped to the speeds met;
//    back up, the amplitude the clip left at the slowest speed, for good, which at a step dt is
//    (v_r - mu_k g dt / 2) / Omega (docs/physics.md: the clipped cycle's half-step lag);
//  - coulomb with mu_s = 1.2 mu_k: once stuck, the stick-slip cycle's amplitude
//    sqrt(x_b^2 + (v_r / Omega)^2) at the speed of each cycle, both ways, until it reaches the
//    tipping offset l/2 - mu_k h_c, where the plate tips.
// Each is a 660 s run of the minimal rig (about 3 s in a release build).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/ramp.hpp"
#include "core/stick_slip_cycle.hpp"
#include "lab/run/experiment.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;  // rad/s per rpm

struct RampRun {
  Scene scene;
  CompiledRig rig;
  RunSummary summary;
  std::vector<CycleRecord> cycles;
};

RampRun run_ramp(const std::vector<SceneOverride>& overrides) {
  RampRun r{test::scene_file("roller-ramp.yaml", overrides), {}, {}, {}};
  r.rig = compile_rig(r.scene);
  RunOptions options;
  options.record_cycles = true;
  RunRecording recording;
  r.summary = run_experiment(r.rig, options, &recording);
  r.cycles = std::move(recording.cycles);
  return r;
}

// The ramp's lowest speed and when it is first and last reached [rad/s, s].
struct Slowest {
  double speed, from, to;
};
Slowest slowest(const std::vector<RampPoint>& ramp) {
  Slowest s{ramp.front().value, 0.0, 0.0};
  for (const RampPoint& p : ramp) s.speed = std::min(s.speed, p.value);
  s.from = std::find_if(ramp.begin(), ramp.end(), [&](const RampPoint& p) {
             return p.value == s.speed;
           })->at;
  s.to = std::find_if(ramp.rbegin(), ramp.rend(), [&](const RampPoint& p) {
           return p.value == s.speed;
         })->at;
  return s;
}

TEST(RampRoundTrip, IdealCoulombKeepsTwentyMillimetresToTheThresholdAndTheClipForGood) {
  const RampRun r = run_ramp({});
  ASSERT_FALSE(r.summary.failure) << *r.summary.failure;
  ASSERT_EQ(r.rig.friction.mu_s, r.rig.friction.mu_k);
  const Ramp ramp(r.scene.rollers.speed_ramp);
  const double a = r.scene.rollers.radius, omega = *r.rig.omega;
  const double a0 = r.rig.amplitude_initial;
  ASSERT_NEAR(a0, 0.020, 1e-12);
  // The slip threshold: the roller speed whose surface speed is the plate's top speed A0 Omega.
  const double threshold = a0 * omega / a;
  EXPECT_NEAR(threshold / kRpm, 154.0, 0.5) << "docs/researchers.md's 154 rpm";

  // Down to the threshold: A0, slipping throughout.
  const CycleRecord* first_stuck = nullptr;
  for (const CycleRecord& c : r.cycles) {
    if (c.stuck()) {
      first_stuck = &c;
      break;
    }
    EXPECT_NEAR(c.amplitude / a0, 1.0, 3e-3) << "cycle at " << c.start << " s";
  }
  // The first stick where the ramp crosses the threshold, within the cycle's speeds (the ramp
  // falls about 1.2 % a period there). At a step dt the solver sticks a contact once the plate's
  // top speed comes within mu_k g dt / 2 of v_r (docs/physics.md), which raises the threshold by
  // that (0.9 % at 1 ms).
  ASSERT_NE(first_stuck, nullptr);
  const double lag = r.rig.friction.mu_k * r.rig.world.gravity * r.scene.world.time_step / 2;
  EXPECT_GE(ramp.at(first_stuck->start), threshold);
  EXPECT_LE(ramp.at(first_stuck->start + first_stuck->period), threshold + lag / a);

  // After the slowest speed, the amplitude the clip left there, for good: slipping, and the
  // clip's settled value at this step.
  const Slowest low = slowest(r.scene.rollers.speed_ramp);
  const double settled = (low.speed * a - lag) / omega;
  EXPECT_NEAR(settled, 6.3e-3, 0.05e-3) << "docs/researchers.md's 6.3 mm";
  int after = 0;
  for (const CycleRecord& c : r.cycles) {
    if (c.start < low.to) continue;
    ++after;
    EXPECT_FALSE(c.stuck()) << "cycle at " << c.start << " s";
    EXPECT_NEAR(c.amplitude / settled, 1.0, 2e-3) << "cycle at " << c.start << " s";
  }
  EXPECT_GT(after, 300);
  EXPECT_EQ(r.summary.regime, Regime::kClipped) << r.summary.regime_evidence;
}

TEST(RampRoundTrip, WithStaticFrictionTheStickSlipCycleFollowsTheSpeedUpToTipping) {
  const RampRun r = run_ramp({{"friction", "{law: coulomb, mu_k: 0.29, mu_s: 0.348}"}});
  ASSERT_FALSE(r.summary.failure) << *r.summary.failure;
  const Ramp ramp(r.scene.rollers.speed_ramp);
  const double a = r.scene.rollers.radius;
  const PlateOnRollers plate{r.rig.rollers.spacing, r.rig.plate.h_c, r.rig.world.gravity};
  const double tipping_offset = r.rig.rollers.spacing / 2 - r.rig.friction.mu_k * r.rig.plate.h_c;
  // The speed whose stick-slip amplitude is the tipping offset, by bisection (the closed form
  // refuses the offset itself).
  double low = 100 * kRpm, high = 1000 * kRpm;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    bool below = true;
    try {
      below = stick_slip_cycle(r.rig.friction, plate, mid * a).amplitude < tipping_offset;
    } catch (const std::exception&) {
      below = false;
    }
    (below ? low : high) = mid;
  }
  const double tipping_speed = low;
  EXPECT_NEAR(tipping_speed / kRpm, 340.0, 10.0) << "docs/researchers.md's 'from about 340 rpm'";
  EXPECT_NEAR(tipping_offset, 44e-3, 0.5e-3) << "docs/researchers.md's 44 mm";

  // The plate tips where the ramp, on its way up, reaches that speed: within one period's
  // change of the speed (1.2 %).
  ASSERT_EQ(r.summary.regime, Regime::kTips) << r.summary.regime_evidence;
  const Slowest slow = slowest(r.scene.rollers.speed_ramp);
  EXPECT_GT(r.summary.regime_since, slow.to);
  EXPECT_NEAR(ramp.at(r.summary.regime_since) / tipping_speed, 1.0, 0.015);

  // Every cycle after the first stick (which starts at A0) until the tipping: stuck, at the
  // stick-slip amplitude of the speeds it met (the ramp changes the speed by about 1.2 % a
  // period, the amplitude follows it within the cycle), on the way down and on the way up. The
  // world finds a stick's end within a step: the break offset x_b is off by at most v_r dt, so
  // A = sqrt(x_b^2 + (v_r / Omega)^2) by at most v_r dt x_b / A, relative at most Omega dt (A is
  // at least v_r / Omega): 0.8 % at 1 ms. Measured: at most 0.53 % below and 0.18 % above.
  const double step_bound = *r.rig.omega * r.scene.world.time_step;
  int down = 0, up = 0, stuck_cycles = 0;
  for (const CycleRecord& c : r.cycles) {
    stuck_cycles += c.stuck() ? 1 : 0;
    if (stuck_cycles < 2 || c.start + c.period >= r.summary.regime_since) continue;
    const std::string where = "cycle at " + std::to_string(c.start) + " s";
    const double v0 = ramp.at(c.start) * a, v1 = ramp.at(c.start + c.period) * a;
    const double theory0 = stick_slip_cycle(r.rig.friction, plate, v0).amplitude;
    const double theory1 = stick_slip_cycle(r.rig.friction, plate, v1).amplitude;
    EXPECT_TRUE(c.stuck()) << where;
    EXPECT_GE(c.amplitude, (1.0 - step_bound) * std::min(theory0, theory1)) << where;
    EXPECT_LE(c.amplitude, (1.0 + step_bound) * std::max(theory0, theory1)) << where;
    (c.start < slow.from ? down : up) += 1;
  }
  EXPECT_GT(down, 80);
  EXPECT_GT(up, 150);
}

}  // namespace
}  // namespace fl
