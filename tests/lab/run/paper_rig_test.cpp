// The paper's rig, whole (scenes/paper-rig.yaml): the plate as built, the motor and the 8:1 gear
// train, the guide towers; against the analytic model and the drive's own physics.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/regime_theory.hpp"
#include "lab/run/run_outputs.hpp"
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
  ASSERT_EQ(r.regime, Regime::kOscillates) << r.regime_evidence;
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

// The drive as Bullet sees it: the roller bodies' own angular velocities (what the contact
// solver used) turn opposite ways at every step of 30 s, each roller's friction pulls the plate
// toward the centre, and the rollers' speed droops under the plate's friction load, measured at
// the contacts, as the motor's linear torque-speed curve says: through the 8:1 gearbox the motor
// carries 8 L for a load torque L at the rollers, so the rollers turn at
// 8 omega_0 (1 - 8 L / tau_stall). A drive that ignored the load would be 1.2 % fast.
TEST(Gearbox, RollersFollowTheMotorsDroopAndTurnOppositeWaysInBullet) {
  Scene s = rig({{"world.duration", "30 s"}});
  s.sensor.reset();
  const CompiledRig compiled = compile_rig(s);
  RigWorld world(compiled);
  const MotorDesc& motor = s.drive->motor;
  const double a = s.rollers.radius;
  double speed_sum = 0.0, load_sum = 0.0;
  long long steps = 0, both_touching = 0;
  bool opposite = true, toward_centre = true;
  for (int i = 0; i < 30000; ++i) {
    world.step();
    const std::array<double, 2> w = world.roller_body_speeds();
    opposite = opposite && w[0] > 0.0 && w[1] < 0.0;
    const std::array<RollerContact, 2> c = world.contacts();
    if (c[0].touching && c[1].touching) {
      ++both_touching;
      toward_centre = toward_centre && c[0].friction_force > 0.0 && c[1].friction_force < 0.0;
    }
    // The torque the plate's friction takes from the two rollers, against their turning.
    load_sum += a * (c[0].friction_force - c[1].friction_force);
    speed_sum += w[0];
    ++steps;
  }
  EXPECT_TRUE(opposite);
  EXPECT_TRUE(toward_centre);
  EXPECT_EQ(both_touching, steps);
  const double load = load_sum / static_cast<double>(steps);
  const double no_load = 8.0 * motor.no_load_speed;
  const double expected = no_load * (1.0 - 8.0 * load / motor.stall_torque);
  EXPECT_LT(expected, 0.99 * no_load);  // the droop is large enough to see
  EXPECT_NEAR(speed_sum / static_cast<double>(steps) / expected, 1.0, 1e-3);
}

// A train the plate's friction stalls (scenes/extreme/gearbox-stall.yaml: the load at the motor
// is twice its stall torque). From its no-load speed w0 the motor decelerates on its linear
// curve, J w' = tau_s (1 - w / w0) - L, and stops at t* = (J w0 / tau_s) ln(r / (r - 1)), r =
// L / tau_s. The drive report measures the ratio and the senses over those turning steps only:
// the design's 8, opposite, and a turning share of t* / duration; averaging the stalled steps
// in would give a ratio near 0.05 and "not opposite". The count of turning steps is within two
// steps of t* (the step that stops the train, and the implicit damper's lag).
TEST(Gearbox, AStalledTrainReportsItsRatioOverTheStepsItTurned) {
  const Scene s = rig({}, "extreme/gearbox-stall");
  const CompiledRig compiled = compile_rig(s);
  ASSERT_TRUE(compiled.drive.has_value());
  const MotorDesc& motor = s.drive->motor;
  const double r = compiled.drive->stall_load_torque / motor.stall_torque;
  ASSERT_GT(r, 1.0);
  const double t_stall = compiled.drive->inertia_at_motor * motor.no_load_speed /
                         motor.stall_torque * std::log(r / (r - 1.0));
  const RunSummary run = run_experiment(s, {});
  ASSERT_TRUE(run.drive.has_value());
  const DriveReport& d = *run.drive;
  EXPECT_NEAR(d.turning_fraction * s.world.duration, t_stall, 2.0 * s.world.time_step);
  ASSERT_TRUE(d.speed_ratio && d.speed_ratio_error && d.senses_opposite);
  EXPECT_NEAR(*d.speed_ratio, 8.0, 1e-9);
  EXPECT_LT(*d.speed_ratio_error, 1e-9);
  EXPECT_TRUE(*d.senses_opposite);
  const std::string text = summary_text(run);
  EXPECT_NE(text.find("8.0000 x the motor while turning"), std::string::npos) << text;
  EXPECT_EQ(text.find("NOT opposite"), std::string::npos) << text;
}

// A motor at zero duty never turns the train: no ratio and no senses were measured, so they are
// null, and the summary says so instead of printing a number.
TEST(Gearbox, ATrainThatNeverTurnedHasNoRatio) {
  const Scene s =
      rig({{"drive.motor.duty", "0 %"}, {"world.duration", "0.2 s"}}, "extreme/gearbox-stall");
  const RunSummary run = run_experiment(s, {});
  ASSERT_TRUE(run.drive.has_value());
  EXPECT_EQ(run.drive->turning_fraction, 0.0);
  EXPECT_FALSE(run.drive->speed_ratio.has_value());
  EXPECT_FALSE(run.drive->speed_ratio_error.has_value());
  EXPECT_FALSE(run.drive->senses_opposite.has_value());
  EXPECT_NE(summary_text(run).find("the train never turned, no ratio measured"), std::string::npos)
      << summary_text(run);
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

// 200 rpm at the rollers (no gearbox): the slip margin falls below 1, the plate reaches a
// roller's speed once and its amplitude is clipped to v_r / Omega (docs/friction-laws.md); the
// paper saw no oscillation at all, which ideal coulomb friction does not give (docs/physics.md).
// Through the gearbox (1600 rpm) it slips throughout.
TEST(Motor, WithoutTheGearboxTheAmplitudeIsClipped) {
  Scene direct = rig({{"drive.gearbox.stages", "[]"}, {"world.duration", "4 s"}});
  EXPECT_EQ(regime_from_theory(compile_rig(direct)).regime, Regime::kClipped);
  const RunSummary clipped = run_experiment(direct, {});
  EXPECT_EQ(clipped.regime, Regime::kClipped) << clipped.regime_evidence;
  EXPECT_LE(clipped.slip_margin, 1.0 + 1e-3);
  ASSERT_TRUE(clipped.amplitude_clipped && clipped.amplitude_clipped_theory);
  // The clip lags by at most one step's kinetic speed change, mu_k g dt (docs/physics.md).
  const double omega = 2.0 * std::numbers::pi / *clipped.period_thick;
  const double lag = direct.friction.mu_k * direct.world.gravity * direct.world.time_step / omega;
  EXPECT_LE(*clipped.amplitude_clipped, *clipped.amplitude_clipped_theory + 1e-6);
  EXPECT_GE(*clipped.amplitude_clipped, *clipped.amplitude_clipped_theory - lag);
  const RunSummary geared = run_experiment(rig({{"world.duration", "4 s"}}), {});
  EXPECT_EQ(geared.regime, Regime::kOscillates);
  EXPECT_GT(geared.slip_margin, 1.0);
}

// The guides hold the plate loosely. Untouched, the plate keeps to y = 0 (no sideways force
// acts); nudged sideways, it stops against a tower, 4.1 mm out (towers' inner faces at 28.1 mm,
// the plate 24 mm wide on each side), and keeps oscillating.
TEST(Guides, ThePlateStaysBetweenTheTowers) {
  {
    RigWorld world(rig());
    for (int i = 0; i < 3000; ++i) world.step();
    EXPECT_NEAR(world.plate().y, 0.0, 1e-14);  // rounding only: 1.7e-15 m after 3 s
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
  RunRecording hall;
  RunOptions record;
  record.record_hall = true;
  const RunSummary r = run_experiment(nudged, record, &hall);
  EXPECT_EQ(r.regime, Regime::kOscillates) << r.regime_evidence;
  // The Hall sensor sees the plate 4 mm sideways: its pulses are smaller than a centred plate's.
  RunRecording centred_hall;
  run_experiment(rig({{"world.duration", "4 s"}}), record, &centred_hall);
  const auto peak = [](const RunRecording& rec, std::size_t from) {
    int lo = 1 << 16, hi = 0;
    for (std::size_t i = from; i < rec.hall.size(); ++i) {
      lo = std::min<int>(lo, rec.hall[i].adc);
      hi = std::max<int>(hi, rec.hall[i].adc);
    }
    return hi - lo;
  };
  // After the first second, when the nudged plate rests against the tower.
  EXPECT_LT(peak(hall, 1000), peak(centred_hall, 1000));
}

}  // namespace
}  // namespace fl
