// The paper's rig, whole (scenes/paper-rig.yaml): the plate as built, the motor and the 8:1 gear
// train, the guide towers; against the analytic model and the drive's own physics.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/experiment.hpp"
#include "lab/regime_theory.hpp"
#include "physics/rig_world.hpp"
#include "scene/drive_layout.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {
namespace {

constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

Scene rig(std::vector<SceneOverride> overrides = {}, const std::string& file = "paper-rig") {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  static const assets::PartCatalog parts =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/" + file + ".yaml", overrides,
      []() -> const PaperTable& { return table; },
      []() -> const assets::PartCatalog& { return parts; });
}

TEST(PaperRig, CentreOfMassComesFromTheParts) {
  const Scene s = rig();
  ASSERT_EQ(s.plate.blocks.size(), 4u);
  // By hand: the slab, four 2x4 bricks at their centre of mass, two magnets on the end bricks.
  const double slab = 1050.0 * 0.200 * 0.048 * 0.0032;
  const double brick = s.plate.blocks[0].mass;
  EXPECT_NEAR(brick, 0.00215, 0.0002);  // a 2x4 brick, about 2.2 g
  const double magnet = 7500.0 * std::numbers::pi * 0.003 * 0.003 * 0.003;
  const double h = (slab * 0.0016 + 4.0 * brick * (0.0032 + s.plate.blocks[0].com_z) +
                    2.0 * magnet * (0.0032 + 0.0096 + 0.0015)) /
                   (slab + 4.0 * brick + 2.0 * magnet);
  EXPECT_NEAR(plate_mass(s).h_c, h, 1e-12);
  EXPECT_NEAR(plate_mass(s).mass, slab + 4.0 * brick + 2.0 * magnet, 1e-12);
}

// The full rig reproduces the minimal scene's physics: within 0.1 % of the thick-plate period
// for the rig's own h_c (guides, blocks and the motor drive included).
TEST(PaperRig, PeriodWithinOneTenthPercentOfTheThickFormula) {
  const RunSummary r = run_experiment(rig(), {});
  ASSERT_EQ(r.regime, "oscillates") << r.regime_evidence;
  ASSERT_TRUE(r.estimator && r.period_thick && r.period_trajectory);
  EXPECT_NEAR(*r.period_trajectory / *r.period_thick - 1.0, 0.0, 1e-3);
  EXPECT_NEAR(r.estimator->period / *r.period_thick - 1.0, 0.0, 1e-3);
}

TEST(PaperRig, SeventySevenKelvinUsesThePapersColdValue) {
  const Scene s = rig({}, "paper-rig-77K");
  EXPECT_DOUBLE_EQ(s.friction.mu_k, 0.20);
  const RunSummary r = run_experiment(s, {});
  ASSERT_TRUE(r.period_thick && r.period_trajectory);
  EXPECT_NEAR(*r.period_trajectory / *r.period_thick - 1.0, 0.0, 1e-3);
}

// Three 2:1 stages from the tooth counts: the rollers turn at 8.000 x the motor, in opposite
// senses, over a 30 s run at 1 kHz.
TEST(Gearbox, RatioEightAndOppositeSensesOverThirtySeconds) {
  Scene s = rig({{"world.duration", "30 s"}});
  s.sensor.reset();
  const RunSummary r = run_experiment(s, {});
  ASSERT_TRUE(r.drive.has_value());
  EXPECT_DOUBLE_EQ(r.drive->gearbox_ratio, 8.0);
  EXPECT_LT(r.drive->speed_ratio_error, 1e-3);
  EXPECT_NEAR(r.drive->speed_ratio, 8.0, 8e-3);
  EXPECT_TRUE(r.drive->senses_opposite);
  EXPECT_GT(r.drive->roller_speeds[0], 0.0);  // roller 0's top turns toward the centre
}

// The layout's gears mesh: neighbouring shafts sit exactly the sum of the pitch radii apart.
TEST(Gearbox, LayoutGearsMesh) {
  const Scene s = rig();
  const DriveLayout layout = drive_layout(s);
  for (const GearMesh& m : layout.meshes) {
    const GearPlacement& a = layout.gears[static_cast<std::size_t>(m.driver)];
    const GearPlacement& b = layout.gears[static_cast<std::size_t>(m.driven)];
    const ShaftPlacement& sa = layout.shafts[static_cast<std::size_t>(a.shaft)];
    const ShaftPlacement& sb = layout.shafts[static_cast<std::size_t>(b.shaft)];
    EXPECT_NEAR(std::hypot(sa.x - sb.x, sa.z - sb.z),
                s.drive->gear(a.teeth).pitch_radius + s.drive->gear(b.teeth).pitch_radius, 1e-12);
    EXPECT_DOUBLE_EQ(a.y, b.y);
  }
}

// The motor slows under the plate's friction as its linear curve says: both rollers slip, so
// together they take mu_k m g a, 8 times that at the motor, and the rollers turn at
// 8 omega_0 (1 - 8 mu_k m g a / tau_stall).
TEST(Motor, DroopUnderThePlatesFrictionFollowsTheLinearCurve) {
  Scene s = rig({{"world.duration", "5 s"}});
  s.sensor.reset();
  const RunSummary r = run_experiment(s, {});
  ASSERT_TRUE(r.drive.has_value());
  const double load = s.friction.mu_k * plate_mass(s).mass * s.world.gravity * s.rollers.radius;
  EXPECT_NEAR(r.drive->load_torque / load, 1.0, 2e-3);
  const double expected = 8.0 * 200.0 * kRpm * (1.0 - 8.0 * load / 0.8);
  EXPECT_NEAR(r.drive->roller_speeds[0] / expected, 1.0, 1e-3);
}

// 200 rpm at the rollers (no gearbox): the slip margin falls below 1 and the plate sticks, as
// the paper saw; through the gearbox (1600 rpm) it slips.
TEST(Motor, WithoutTheGearboxThePlateSticks) {
  Scene direct = rig({{"drive.gearbox.stages", "[]"}, {"world.duration", "4 s"}});
  EXPECT_EQ(regime_from_theory(direct).regime, "sticks");
  const RunSummary stuck = run_experiment(direct, {});
  EXPECT_EQ(stuck.regime, "sticks") << stuck.regime_evidence;
  EXPECT_LE(stuck.slip_margin, 1.0 + 1e-3);
  const RunSummary geared = run_experiment(rig({{"world.duration", "4 s"}}), {});
  EXPECT_EQ(geared.regime, "oscillates");
  EXPECT_GT(geared.slip_margin, 1.0);
}

// The guides hold the plate loosely. Untouched, the plate keeps to y = 0 (no sideways force
// acts); nudged sideways, it stops against a tower, 4.1 mm out (towers' inner faces at 28.1 mm,
// the plate 24 mm wide on each side), and keeps oscillating.
TEST(Guides, ThePlateStaysBetweenTheTowers) {
  {
    RigWorld world(rig());
    for (int i = 0; i < 3000; ++i) world.step();
    EXPECT_NEAR(world.plate().y, 0.0, 1e-9);
  }
  Scene nudged = rig({{"plate.sideways_velocity", "0.1 m/s"}, {"world.duration", "4 s"}});
  RigWorld world(nudged);
  double y_max = 0.0;
  for (int i = 0; i < 4000; ++i) {
    world.step();
    y_max = std::max(y_max, world.plate().y);
  }
  EXPECT_GT(y_max, 0.003);   // it reached the tower ...
  EXPECT_LT(y_max, 0.0045);  // ... and went no farther than the clearance (plus contact slop)
  const RunSummary r = run_experiment(nudged, {});
  EXPECT_EQ(r.regime, "oscillates") << r.regime_evidence;
}

}  // namespace
}  // namespace fl
