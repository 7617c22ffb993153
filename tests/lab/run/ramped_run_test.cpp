// A run whose rollers ramp down through the slip threshold, under ideal Coulomb friction
// (mu_s = mu_k), cut into cycles: every cycle's period is the thick-plate period (full slip, or the
// clipped cycle, whose period is unchanged: core/stick_slip_cycle.hpp); above the threshold
// (v_r > A0 Omega) the amplitude keeps its start A0 (Coulomb friction with full slip conserves
// the energy); below it, each cycle's amplitude is clipped to v_r / Omega at the speeds the
// plate met within the cycle. And the cycles' CSV writes what the tracker measured.
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/stick_slip_cycle.hpp"
#include "lab/run/cycle_report.hpp"
#include "lab/run/experiment.hpp"

namespace fl {
namespace {

constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;  // rad/s per rpm

TEST(RampedRun, IdealCoulombPeriodStaysThickAndAmplitudeIsClippedBelowTheThreshold) {
  Scene scene;  // the minimal rig: l = 89 mm, a = 10 mm, A0 = 20 mm from rest, mu_k = 0.29
  scene.world.duration = 125.0;
  // 400 rpm (above the threshold for A0: about 152 rpm) down to 60 rpm over 120 s.
  scene.rollers.speed_ramp = {{0.0, 400 * kRpm}, {2.0, 400 * kRpm}, {122.0, 60 * kRpm}};
  const CompiledRig rig = compile_rig(scene);
  RunOptions options;
  options.record_cycles = true;
  RunRecording recording;
  const RunSummary summary = run_experiment(rig, options, &recording);
  ASSERT_FALSE(summary.failure) << *summary.failure;
  const Ramp ramp(scene.rollers.speed_ramp);
  const double a = scene.rollers.radius;
  const double omega = *rig.omega;
  const double period = *rig.period_thick;
  const double a0 = rig.amplitude_initial;
  ASSERT_NEAR(a0, 0.020, 1e-12);
  // The clipped cycle of core/stick_slip_cycle.hpp at mu_s = mu_k: amplitude v_r / Omega, the
  // period unchanged.
  const PlateOnRollers plate{rig.rollers.spacing, rig.plate.h_c, rig.world.gravity};
  const StickSlipCycle clipped = stick_slip_cycle(rig.friction, plate, 0.1);
  ASSERT_TRUE(clipped.clipped);
  ASSERT_NEAR(clipped.period, period, 1e-12 * period);

  int above = 0, below = 0;
  for (const CycleRecord& c : recording.cycles) {
    const double v_start = ramp.at(c.start) * a, v_end = ramp.at(c.start + c.period) * a;
    const std::string where = "cycle at " + std::to_string(c.start) + " s, " +
                              std::to_string(c.surface_speed_mean / a / kRpm) + " rpm";
    // The period of the thick plate: within 0.05 % in full slip (the lab's period claim for runs,
    // scenes/sweeps/spacing.yaml); a clipped cycle touches the rollers' speed twice, and the
    // world resolves each touch to a step: within two steps more.
    const double dt = scene.world.time_step;
    EXPECT_NEAR(c.period, period, 5e-4 * period + (c.stuck() ? 2.0 * dt : 0.0)) << where;
    if (std::max(v_start, v_end) < a0 * omega) {
      // Below the threshold: clipped at the speeds met within the cycle, v_end <= v_r <= v_start,
      // to within 0.3 % (the trajectory's own drift and the step's resolution of the touch).
      ++below;
      EXPECT_GE(c.amplitude, 0.997 * v_end / omega) << where;
      EXPECT_LE(c.amplitude, 1.003 * v_start / omega) << where;
      EXPECT_TRUE(c.stuck()) << where;
    } else if (std::min(v_start, v_end) > 1.02 * a0 * omega && c.start + c.period < 60.0) {
      // Well above it (and before the clip): the start amplitude, within 0.3 %.
      ++above;
      EXPECT_NEAR(c.amplitude / a0, 1.0, 3e-3) << where;
      EXPECT_FALSE(c.stuck()) << where;
    }
  }
  EXPECT_GT(above, 30);
  EXPECT_GT(below, 30);
  // The last cycles sit at the clip of the ramp's end, 60 rpm: v_r / Omega = 7.9 mm.
  EXPECT_NEAR(recording.cycles.back().amplitude / (60 * kRpm * a / omega), 1.0, 0.01);
}

TEST(RampedRun, CyclesCsvHasARowPerCycleAndTheRampsDirection) {
  Scene scene;
  scene.world.duration = 8.0;
  scene.rollers.speed_ramp = {{0.0, 300 * kRpm}, {4.0, 600 * kRpm}, {8.0, 300 * kRpm}};
  const CompiledRig rig = compile_rig(scene);
  RunOptions options;
  options.record_cycles = true;
  RunRecording recording;
  run_experiment(rig, options, &recording);
  ASSERT_GE(recording.cycles.size(), 8u);
  const std::string csv = cycles_csv(rig, recording.cycles);
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("start_s,period_s,amplitude_m,", 0), 0u) << line;
  std::size_t rows = 0, up = 0, down = 0;
  while (std::getline(in, line)) {
    ++rows;
    up += line.find(",up,") != std::string::npos;
    down += line.find(",down,") != std::string::npos;
  }
  EXPECT_EQ(rows, recording.cycles.size());
  EXPECT_GE(up, 3u);
  EXPECT_GE(down, 3u);
  EXPECT_EQ(up + down, rows);  // no cycle of this ramp is held
  // A run without a ramp holds.
  EXPECT_EQ(ramp_direction(compile_rig(Scene{}), recording.cycles.front()), "hold");
}

}  // namespace
}  // namespace fl
