// The world follows a scheduled roller speed: with a speed ramp, the rollers' measured speed at
// every step (and the speed Bullet's solver used) is the schedule's at that time, in opposite
// senses; with a duty ramp, the motor drive reaches the loaded speed of each held duty, and a ramp
// that holds one duty gives the constant duty's trajectory bit for bit.
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/paper_table_yaml.hpp"
#include "physics/rig_world.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {
namespace {

constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;  // rad/s per rpm

TEST(RollerRamp, MeasuredSpeedIsTheScheduleAtEveryStep) {
  Scene scene;
  scene.rollers.speed_ramp = {{0.0, 100 * kRpm}, {0.5, 1600 * kRpm}, {1.0, 100 * kRpm}};
  const Ramp ramp(scene.rollers.speed_ramp);
  RigWorld world(scene);
  EXPECT_DOUBLE_EQ(world.roller_speeds()[0], 100 * kRpm);
  int checked = 0;
  while (world.time() < 1.5 - 1e-9) {
    world.step();
    const double t = world.time();
    const double expected = ramp.at(t);
    ASSERT_NEAR(world.roller_speeds()[0], expected, 1e-12 * expected) << t;
    ASSERT_NEAR(world.roller_speeds()[1], -expected, 1e-12 * expected) << t;
    ASSERT_NEAR(world.roller_body_speeds()[0], expected, 1e-9 * expected) << t;
    ASSERT_NEAR(world.roller_surface_speeds()[0], expected * scene.rollers.radius, 1e-12) << t;
    ++checked;
  }
  EXPECT_EQ(checked, 1500);
  // The named instants: a quarter of the way, the top, and held after the last point.
  RigWorld again(scene);
  for (const auto& [t, rpm] : std::vector<std::pair<double, double>>{
           {0.25, 850.0}, {0.5, 1600.0}, {0.75, 850.0}, {1.2, 100.0}}) {
    while (again.time() < t - 1e-9) again.step();
    EXPECT_NEAR(again.roller_speeds()[0] / kRpm, rpm, 1e-9) << t;
  }
}

// The paper's rig's motor (scenes/paper-rig.yaml) with a duty ramp instead of its duty.
SceneOverride motor_with(const std::string& duty) {
  return {"drive.motor",
          "{rated_voltage: 12 V, no_load_speed: 200 rpm, stall_torque: 0.8 N m, inertia: 5e-4 kg "
          "m^2, " +
              duty + "}"};
}

Scene paper_rig(const std::vector<SceneOverride>& overrides) {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  static const assets::PartCatalog parts =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/paper-rig.yaml", overrides,
      []() -> const PaperTable& { return table; },
      []() -> const assets::PartCatalog& { return parts; });
}

TEST(DutyRamp, AHeldRampIsTheConstantDutyBitForBit) {
  const Scene constant = paper_rig({motor_with("duty: 60 %")});
  const Scene ramped =
      paper_rig({motor_with("duty_ramp: [{at: 0 s, duty: 60 %}, {at: 1 s, duty: 60 %}]")});
  RigWorld a(constant), b(ramped);
  for (int i = 0; i < 2000; ++i) {
    a.step();
    b.step();
  }
  const PlateState sa = a.plate(), sb = b.plate();
  EXPECT_EQ(std::memcmp(&sa, &sb, sizeof sa), 0);
  EXPECT_EQ(a.roller_speeds(), b.roller_speeds());
}

TEST(DutyRamp, TheDriveReachesEachHeldDutysLoadedSpeed) {
  // 30 % for 1 s, then up to 100 % over 1 s, held. On the motor's linear curve with the plate
  // sliding on both rollers (friction torque mu_k m g a at the rollers), the rollers settle at
  // G omega_0 (duty - load / stall): the compiled rig's loaded speed at that duty.
  const Scene scene = paper_rig({motor_with(
      "duty_ramp: [{at: 0 s, duty: 30 %}, {at: 1 s, duty: 30 %}, {at: 2 s, duty: 100 %}]")});
  RigWorld world(scene);
  const CompiledRig& rig = world.rig();
  const MotorDesc& motor = scene.drive->motor;
  const double G = rig.drive->gearbox_ratio;
  const double load = rig.drive->stall_load_torque / motor.stall_torque;
  const auto loaded = [&](double duty) { return G * motor.no_load_speed * (duty - load); };
  // The compiled loaded speed is the ramp's smallest duty's.
  ASSERT_TRUE(rig.drive->roller_speed_loaded.has_value());
  EXPECT_NEAR(*rig.drive->roller_speed_loaded, loaded(0.3), 1e-9);
  EXPECT_NEAR(rig.roller_speed_nominal, G * motor.no_load_speed, 1e-9);  // the largest duty's
  // The rollers' mean |speed| over the last 0.2 s of each hold (the plate's friction on them
  // swings with its motion; its mean is the sliding load).
  const auto mean_speed = [&](double from, double to) {
    while (world.time() < from - 1e-9) world.step();
    double sum = 0.0;
    int n = 0;
    while (world.time() < to - 1e-9) {
      world.step();
      sum += std::fabs(world.roller_speeds()[0]);
      ++n;
    }
    return sum / n;
  };
  EXPECT_NEAR(mean_speed(0.8, 1.0) / loaded(0.3), 1.0, 0.02);
  EXPECT_NEAR(mean_speed(3.8, 4.0) / loaded(1.0), 1.0, 0.02);
}

}  // namespace
}  // namespace fl
