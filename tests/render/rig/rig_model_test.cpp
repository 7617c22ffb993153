// The rig renderer's geometry, without GL: the LEGO frame merged with only hidden faces left out,
// gears whose teeth interleave on their shafts, blur at speed, camera presets that frame the rig,
// a scene without LEGO parts built without the part index or any mesh; the overlay's numbers and
// title card; the video's settings and frame clock; the scene's `video` keys.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "cli/field_spelling.hpp"
#include "io/input_error.hpp"
#include "lab/video/video_settings.hpp"
#include "render/rig/force_overlay.hpp"
#include "render/rig/motion_strip.hpp"
#include "render/rig/phase_portrait.hpp"
#include "render/rig/rig_camera.hpp"
#include "render/rig/rig_model.hpp"
#include "render/rig/rig_overlay.hpp"
#include "scene/drive_layout.hpp"
#include "scene/video_format.hpp"
#include "support/rig_fixture.hpp"

namespace fl::render {
namespace {

constexpr double kPi = std::numbers::pi;

#define FL_REQUIRE_ASSETS()                                                                    \
  do {                                                                                         \
    if (!assets::kHasAssets) GTEST_SKIP() << "built without FRICTIONLAB_WITH_ASSETS (assimp)"; \
  } while (0)

using test::paper_rig_model;

// What effective_video refuses a request with, or "" when it takes it.
std::string request_error(const Scene& scene, const VideoRequest& request) {
  try {
    effective_video(scene, request);
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

// A scene with a frame of the given parts (YAML list items) and nothing else special.
Scene frame_scene(const std::string& parts) {
  const std::string text = R"(format: 1
rollers: {spacing: 89 mm, radius: 10 mm}
plate: {length: 200 mm, thickness: 5 mm, offset: 20 mm}
friction: {mu_k: 0.3}
frame:
  origin: [0 mm, 100 mm, -40 mm]
  parts:
)" + parts;
  return load_scene_text(
      text, "frame.yaml", {}, []() -> const PaperTable& { return test::paper_table(); },
      []() -> const assets::PartCatalog& { return test::part_catalog(); });
}

TEST(RigModel, TheFrameLeavesOutOnlyWhatNoCameraSees) {
  FL_REQUIRE_ASSETS();
  const RigModel rig = paper_rig_model();
  EXPECT_EQ(rig.stats.frame_parts, test::paper_rig().frame->parts.size());
  // Stacked bricks hide their studs and cavities: about half the frame's triangles go.
  EXPECT_LT(rig.stats.frame_triangles_drawn, rig.stats.frame_triangles_full * 6 / 10);
  EXPECT_GT(rig.stats.frame_triangles_drawn, rig.stats.frame_triangles_full * 3 / 10);
  std::cout << "paper rig: LEGO frame " << rig.stats.frame_triangles_drawn << " of "
            << rig.stats.frame_triangles_full << " triangles drawn; "
            << rig.triangles(rest_pose(compile_rig(test::paper_rig())), 0.0) << " in all at rest\n";

  // One brick on the table keeps everything but its underside (cavity and rim) ...
  const Scene one = frame_scene("    - {part: brick-2x4, at: [0, 0, 0]}\n");
  assets::MeshLibrary library;
  const RigModel single = build_rig_model(compile_rig(one), &test::part_catalog(), &library);
  const std::size_t brick = test::part_catalog().at("brick-2x4").triangles;
  EXPECT_EQ(single.stats.frame_triangles_full, brick);
  EXPECT_LT(single.stats.frame_triangles_drawn, brick);
  // ... its studs among them: the frame's highest point is a stud's top.
  float top = -1.0f;
  for (const auto& v : single.meshes[single.parts[0].mesh].positions) top = std::max(top, v.z());
  EXPECT_NEAR(static_cast<double>(top), -0.040 + assets::kBrickHeight + assets::kStudHeight, 1e-5);

  // A brick on top hides the lower one's studs and its own cavity: fewer than two singles.
  const Scene two = frame_scene(
      "    - {part: brick-2x4, at: [0, 0, 0]}\n    - {part: brick-2x4, at: [0, 0, 3]}\n");
  assets::MeshLibrary meshes;
  const RigModel stack = build_rig_model(compile_rig(two), &test::part_catalog(), &meshes);
  EXPECT_EQ(stack.stats.frame_triangles_full, 2 * brick);
  EXPECT_LT(stack.stats.frame_triangles_drawn, 2 * single.stats.frame_triangles_drawn - 8 * 40);
  std::size_t studs_between = 0;
  for (const auto& v : stack.meshes[stack.parts[0].mesh].positions) {
    const float z = v.z() - (-0.040f + static_cast<float>(assets::kBrickHeight));
    studs_between += (z > 1e-4f && z < 0.0016f) ? 1 : 0;
  }
  EXPECT_EQ(studs_between, 0u) << "the lower brick's studs are inside the upper brick";
  // The library read the brick's mesh once (and the rollers' axle).
  EXPECT_EQ(meshes.files_read(), 2u);
}

TEST(RigModel, ARigWithoutLegoPartsNeedsNoIndexAndNoMesh) {
  const Scene scene = test::scene_file("minimal.yaml");
  ASSERT_FALSE(rig_uses_parts(compile_rig(scene)));
  // No catalogue, no mesh library: built from boxes and cylinders alone.
  const RigModel rig = build_rig_model(compile_rig(scene), nullptr, nullptr);
  EXPECT_EQ(rig.stats.meshes_read, 0u);
  EXPECT_EQ(rig.stats.frame_parts, 0u);
  EXPECT_EQ(rig.shafts.size(), 2u);
  EXPECT_GT(rig.triangles(rest_pose(compile_rig(scene)), 0.0), 500u);
  // The paper's rig does need them.
  EXPECT_TRUE(rig_uses_parts(compile_rig(test::paper_rig())));
  EXPECT_THROW(build_rig_model(compile_rig(test::paper_rig()), nullptr, nullptr),
               std::invalid_argument);
}

// The gear drawn for `placement` turned to its angle at `pose`: the angle about +y of its tooth 0.
double tooth_angle(const RigModel& rig, const RigPose& pose, std::size_t gear_part) {
  const RigPart& part = rig.parts[gear_part];
  return pose.shaft_angles[static_cast<std::size_t>(part.shaft)] + part.phase;
}

TEST(RigModel, MeshingGearsPutATeethIntoTheOthersGaps) {
  FL_REQUIRE_ASSETS();
  const Scene& scene = test::paper_rig();
  const DriveLayout layout = drive_layout(scene);
  const RigModel rig = paper_rig_model();
  // The gear parts, in the layout's order, are the last parts of the model.
  const std::size_t first_gear = rig.parts.size() - layout.gears.size();
  RigPose pose = rest_pose(compile_rig(scene));
  for (const double turn : {0.0, 0.37, 2.9}) {
    // The train turned from rest: each shaft by the tooth-count ratio, in alternate senses.
    std::vector<double> angle(layout.shafts.size(), 0.0);
    std::vector<bool> set(layout.shafts.size(), false);
    angle[static_cast<std::size_t>(layout.motor)] = turn;
    set[static_cast<std::size_t>(layout.motor)] = true;
    for (int pass = 0; pass < 2; ++pass) {
      for (const GearMesh& m : layout.meshes) {
        const GearPlacement& a = layout.gears[static_cast<std::size_t>(m.driver)];
        const GearPlacement& b = layout.gears[static_cast<std::size_t>(m.driven)];
        if (!set[static_cast<std::size_t>(a.shaft)]) continue;
        angle[static_cast<std::size_t>(b.shaft)] =
            -angle[static_cast<std::size_t>(a.shaft)] * a.teeth / b.teeth;
        set[static_cast<std::size_t>(b.shaft)] = true;
      }
    }
    pose.shaft_angles = angle;
    for (const GearMesh& m : layout.meshes) {
      const GearPlacement& a = layout.gears[static_cast<std::size_t>(m.driver)];
      const GearPlacement& b = layout.gears[static_cast<std::size_t>(m.driven)];
      const ShaftPlacement& sa = layout.shafts[static_cast<std::size_t>(a.shaft)];
      const ShaftPlacement& sb = layout.shafts[static_cast<std::size_t>(b.shaft)];
      // The direction from a's axis to b's, measured like a turn about +y.
      const double alpha = std::atan2(-(sb.z - sa.z), sb.x - sa.x);
      const double pitch_a = 2 * kPi / a.teeth;
      const double pitch_b = 2 * kPi / b.teeth;
      const double ta = tooth_angle(rig, pose, first_gear + static_cast<std::size_t>(m.driver));
      const double tb = tooth_angle(rig, pose, first_gear + static_cast<std::size_t>(m.driven));
      // Where each gear's teeth stand against the line between the axes, in teeth. Turning
      // moves one gear's teeth toward the contact as fast as the other's move away, so their
      // sum is fixed: half a tooth, each tooth facing a gap.
      const double fa = (alpha - ta) / pitch_a;
      const double fb = (alpha + kPi - tb) / pitch_b;
      EXPECT_NEAR(std::fabs(std::remainder(fa + fb, 1.0)), 0.5, 1e-6)
          << a.teeth << " -> " << b.teeth << " at a turn of " << turn;
    }
  }
}

TEST(RigModel, FastPartsAreDrawnBlurred) {
  FL_REQUIRE_ASSETS();
  const RigModel rig = paper_rig_model();
  RigPose pose = rest_pose(compile_rig(test::paper_rig()));
  const std::size_t still = rig.triangles(pose, 1.0 / 120.0);
  // 1600 rpm at the rollers, 960 rpm at the idlers, 200 rpm at the motor.
  const auto& shafts = rig.shafts;
  for (std::size_t s = 0; s < shafts.size(); ++s) {
    double speed = 167.55;
    if (shafts[s].role == "motor") speed = 20.94;
    if (shafts[s].role.rfind("idler", 0) == 0) speed = 100.5;
    if (shafts[s].role.rfind("stage", 0) == 0) speed = 41.9;
    pose.shaft_speeds[s] = speed;
  }
  // The blurred teeth of the fast gears are rings with far fewer triangles.
  EXPECT_LT(rig.triangles(pose, 1.0 / 120.0), still - 5000);
  // A roller picks its smeared variant; the motor's gear stays sharp.
  for (const RigPart& part : rig.parts) {
    if (part.body != RigPart::Body::kShaft || part.blur_variants.empty()) continue;
    const PlacedPart placed = place_part(rig, part, pose, 1.0 / 120.0);
    if (part.shaft < 2 && part.blur_variants.size() == kBlurSweeps.size() &&
        part.blur_variants[0] != part.blur_variants[1]) {
      EXPECT_NE(placed.mesh, part.mesh);  // a roller at speed
    }
    if (shafts[static_cast<std::size_t>(part.shaft)].role == "motor") {
      EXPECT_EQ(placed.mesh, part.mesh);
    }
    // Standing still, everything is sharp.
    EXPECT_EQ(place_part(rig, part, rest_pose(compile_rig(test::paper_rig())), 1.0 / 120.0).mesh,
              part.mesh);
  }
}

TEST(RigModel, CameraPresetsFrameTheWholeRig) {
  FL_REQUIRE_ASSETS();
  const RigModel rig = paper_rig_model();
  for (const std::string_view preset : kCameraPresets) {
    VideoDesc video;
    video.width = 640;
    video.height = 360;
    video.camera = std::string(preset);
    const Camera camera = rig_camera(rig, video);
    if (preset == "sensor") {
      const auto at = project_to_pixel(camera, 640, 360, rig.sensor);
      ASSERT_TRUE(at.has_value());
      EXPECT_NEAR(at->x(), 320.0f, 160.0f);
      EXPECT_LT(at->y(), 0.70f * 360.0f);
      continue;
    }
    if (preset == "phone") {
      // The whole rig in the picture, and the plate's motion level and across it: points along
      // x at the plate's height land on one row, and the swing's two ends equally far from the
      // middle (square on).
      for (const auto& point : rig.outline) {
        const auto at = project_to_pixel(camera, 640, 360, point);
        ASSERT_TRUE(at.has_value());
        EXPECT_GE(at->x(), 0.0f);
        EXPECT_LE(at->x(), 640.0f);
        EXPECT_GE(at->y(), 0.0f);
        EXPECT_LE(at->y(), 360.0f);
      }
      const auto left = project_to_pixel(camera, 640, 360, Eigen::Vector3f(-0.03f, 0.0f, 0.004f));
      const auto right = project_to_pixel(camera, 640, 360, Eigen::Vector3f(0.03f, 0.0f, 0.004f));
      const auto middle = project_to_pixel(camera, 640, 360, Eigen::Vector3f(0.0f, 0.0f, 0.004f));
      ASSERT_TRUE(left && right && middle);
      EXPECT_NEAR(left->y(), right->y(), 0.5f);
      EXPECT_NEAR(middle->x() - left->x(), right->x() - middle->x(), 0.5f);
      continue;
    }
    // Every part of the rig lands in the picture, above the overlay's bottom panels.
    for (const auto& point : rig.outline) {
      const auto at = project_to_pixel(camera, 640, 360, point);
      ASSERT_TRUE(at.has_value()) << preset;
      EXPECT_GE(at->x(), 0.0f) << preset;
      EXPECT_LE(at->x(), 640.0f) << preset;
      EXPECT_GE(at->y(), 0.07f * 360.0f) << preset;
      EXPECT_LE(at->y(), 0.71f * 360.0f) << preset;
    }
  }
  // The orbit turns the camera about the vertical through its target, keeping its distance.
  VideoDesc video;
  const Camera camera = rig_camera(rig, video);
  const Camera turned = orbit_camera(camera, kPi / 2);
  EXPECT_NEAR((turned.position - turned.target).norm(), (camera.position - camera.target).norm(),
              1e-5);
  EXPECT_NEAR(turned.position.z(), camera.position.z(), 1e-6);
  EXPECT_GT((turned.position - camera.position).norm(), 0.05f);
}

// The front camera looks from -y through the near wall: a cutaway leaves out exactly the frame's
// parts wholly on that side of the plate, and the camera then sees both rollers' near ends
// nearer than anything of the frame.
TEST(RigModel, TheFrontCutawayLeavesOutTheNearWallOnly) {
  FL_REQUIRE_ASSETS();
  const Scene& scene = test::paper_rig();
  assets::MeshLibrary meshes;
  const RigModel cut = build_rig_model(compile_rig(scene), &test::part_catalog(), &meshes, true);
  const double near_edge = -0.5 * scene.plate.width;
  std::size_t near_parts = 0;
  for (const FramePart& part : scene.frame->parts) {
    const assets::PartSpec* spec = test::part_catalog().find(part.part);
    ASSERT_NE(spec, nullptr);
    // A part's far face: its origin plus its mesh's extent along y (turned parts stand at +y).
    if (part.turn == 0 && part.position[1] + spec->bounds.max[1] < near_edge) ++near_parts;
  }
  EXPECT_GT(near_parts, 0u);
  EXPECT_EQ(cut.stats.cut_away_parts, near_parts);
  EXPECT_EQ(paper_rig_model().stats.cut_away_parts, 0u);
}

// The front preset keeps the rig off the motion strip (top right) and the weight panel (left).
TEST(RigModel, TheFrontCameraKeepsTheRigOffThePanels) {
  FL_REQUIRE_ASSETS();
  assets::MeshLibrary meshes;
  const RigModel model =
      build_rig_model(compile_rig(test::paper_rig()), &test::part_catalog(), &meshes, true);
  VideoDesc video;
  video.width = 1280;
  video.height = 720;
  const Camera camera = rig_camera(model, video);
  const float s = overlay_scale(1280, 720);
  const Rect strip{1280 - 276 * s, 28 * s, 268 * s, 88 * s};
  int inside = 0, seen = 0;
  for (const Eigen::Vector3f& point : model.outline) {
    const auto p = project_to_pixel(camera, 1280, 720, point);
    ASSERT_TRUE(p);
    ++seen;
    if (p->x() > strip.x && p->y() < strip.y + strip.height) ++inside;
  }
  EXPECT_GT(seen, 100);
  EXPECT_EQ(inside, 0);
}

TEST(ForceOverlay, WeightSharesAreEachRollersPartOfTheLoad) {
  PlateForces forces;
  forces.rollers[0] = ContactForce{true, 0.3, 0.09, Eigen::Vector3f::Zero()};
  forces.rollers[1] = ContactForce{true, 0.1, -0.03, Eigen::Vector3f::Zero()};
  const auto shares = weight_shares(forces);
  ASSERT_TRUE(shares);
  EXPECT_DOUBLE_EQ((*shares)[0], 0.75);
  EXPECT_DOUBLE_EQ((*shares)[1], 0.25);
  // A plate off roller 1 rests wholly on roller 0; off both, it is in the air.
  forces.rollers[1].touching = false;
  EXPECT_DOUBLE_EQ((*weight_shares(forces))[0], 1.0);
  forces.rollers[0].touching = false;
  EXPECT_FALSE(weight_shares(forces));
}

// The arrows: the normal forces up the picture, each roller's friction toward the middle (the
// rollers' tops turn inward), the net friction the sum of the two, all to one scale.
TEST(ForceOverlay, ArrowsPointAlongTheirForcesToOneScale) {
  Camera camera;  // the default: from the front, right and above
  PlateForces forces;
  forces.rollers[0] = ContactForce{true, 0.3, 0.087, Eigen::Vector3f(-0.0445f, -0.024f, 0.0f)};
  forces.rollers[1] = ContactForce{true, 0.1, -0.029, Eigen::Vector3f(0.0445f, -0.024f, 0.0f)};
  forces.centre = Eigen::Vector3f(-0.02f, -0.024f, 0.0036f);
  const ForceScale scale = force_scale(camera, 1280, 720, Eigen::Vector3f::Zero(), 0.089, 0.4);
  const double per_newton = static_cast<double>(scale.pixels_per_newton);
  // 0.1 N: the largest of 1, 2, 5 x 10^k at most a quarter of the 0.4 N weight.
  EXPECT_DOUBLE_EQ(scale.reference_force, 0.1);
  EXPECT_DOUBLE_EQ(
      force_scale(camera, 1280, 720, Eigen::Vector3f::Zero(), 0.089, 4.1).reference_force, 1.0);
  EXPECT_DOUBLE_EQ(
      force_scale(camera, 1280, 720, Eigen::Vector3f::Zero(), 0.089, 0.9).reference_force, 0.2);
  const std::vector<ForceArrow> arrows = force_arrows(camera, 1280, 720, forces, scale);
  ASSERT_EQ(arrows.size(), 5u);
  const auto length = [](const ForceArrow& a) {
    return static_cast<double>((a.to - a.from).norm());
  };
  const auto dx = [](const ForceArrow& a) { return static_cast<double>(a.to.x() - a.from.x()); };
  // F0, F1, the net friction, N0, N1.
  EXPECT_GT(dx(arrows[0]), 0.0);                    // F0 toward +x
  EXPECT_LT(dx(arrows[1]), 0.0);                    // F1 toward -x
  EXPECT_LT(arrows[3].to.y(), arrows[3].from.y());  // N0 up the picture
  EXPECT_LT(arrows[4].to.y(), arrows[4].from.y());  // N1
  EXPECT_NEAR(length(arrows[3]) / length(arrows[4]), 3.0, 1e-4);
  EXPECT_NEAR(length(arrows[3]), 0.3 * per_newton, 1e-3);
  EXPECT_NEAR(length(arrows[2]), (0.087 - 0.029) * per_newton, 1e-3);
  EXPECT_EQ(arrows[2].label, "F\xe2\x82\x80 + F\xe2\x82\x81");
  // Half the weight spans 0.35 of the spacing's projection.
  const auto a = project_to_pixel(camera, 1280, 720, Eigen::Vector3f(-0.0445f, 0.0f, 0.0f));
  const auto b = project_to_pixel(camera, 1280, 720, Eigen::Vector3f(0.0445f, 0.0f, 0.0f));
  EXPECT_NEAR(0.2 * per_newton, 0.35 * static_cast<double>((*b - *a).norm()), 1e-2);
}

// The strip's theory: x0 cos(omega t) + v0 / omega sin(omega t), and the simulated curve read
// between its samples.
TEST(MotionStrip, TheTheoryIsTheThickPlatesHarmonicMotion) {
  const double omega = 2.0 * kPi / 0.7766;
  const HarmonicMotion released{0.03, 0.0, omega};
  EXPECT_NEAR(released.at(0.7766), 0.03, 1e-12);
  EXPECT_NEAR(released.at(0.7766 / 2.0), -0.03, 1e-12);
  EXPECT_NEAR(released.at(0.7766 / 4.0), 0.0, 1e-12);
  const HarmonicMotion pushed{0.0, 0.2, omega};
  EXPECT_NEAR(pushed.at(0.7766 / 4.0), 0.2 / omega, 1e-12);  // its amplitude v0 / omega
  const std::vector<Eigen::Vector2d> samples{{0.0, 0.01}, {0.1, 0.02}, {0.2, 0.0}};
  EXPECT_NEAR(*position_at(samples, 0.05), 0.015, 1e-12);
  EXPECT_NEAR(*position_at(samples, 0.15), 0.01, 1e-12);
  EXPECT_EQ(*position_at(samples, -1.0), 0.01);
  EXPECT_EQ(*position_at(samples, 9.0), 0.0);
  EXPECT_FALSE(position_at({}, 0.0));
}

// The portrait's theory is the strip's curve and its derivative; its axes hold the ellipse and
// the trace, and the slip limit when it is near.
TEST(PhasePortrait, TheEllipseIsTheCurvesDerivativeAndTheAxesHoldIt) {
  const double omega = 2.0 * kPi / 0.7766;
  const HarmonicMotion c{0.03, 0.05, omega};
  for (const double t : {0.0, 0.1, 0.37, 0.9}) {
    // A central difference: independent of the closed form.
    const double h = 1e-6;
    EXPECT_NEAR(c.velocity_at(t), (c.at(t + h) - c.at(t - h)) / (2.0 * h), 1e-7) << t;
    // The ellipse: (x omega)^2 + v^2 is the same all the way round.
    EXPECT_NEAR(std::pow(c.at(t) * omega, 2) + std::pow(c.velocity_at(t), 2),
                std::pow(0.03 * omega, 2) + 0.05 * 0.05, 1e-12);
  }
  PhasePortraitState state;
  state.t = 3.0;
  state.theory = c;
  state.x_range = 0.035;
  const double top = std::hypot(0.03 * omega, 0.05);
  // The paper's rig: v_r = 1.66 m/s, eight times the plate's top speed: named, not drawn.
  state.slip_speed = 1.66;
  PhaseAxes axes = phase_axes(state);
  EXPECT_NEAR(axes.v_range, 1.15 * top, 1e-12);
  EXPECT_FALSE(axes.slip_in_view);
  EXPECT_DOUBLE_EQ(axes.x_range, 0.035);
  // Slow rollers: the slip limit inside the ellipse's speeds joins the view.
  state.slip_speed = 0.2;
  axes = phase_axes(state);
  EXPECT_TRUE(axes.slip_in_view);
  EXPECT_NEAR(axes.v_range, 1.15 * top, 1e-12);
  state.slip_speed = 0.5;
  EXPECT_NEAR(phase_axes(state).v_range, 0.55, 1e-12);
  // A trace faster than the theory widens the axes; points outside the window do not.
  const std::vector<Eigen::Vector3d> trace{{0.1, 0.0, 0.9}, {2.0, 0.0, -0.4}, {3.0, 0.01, 0.1}};
  state.simulated = trace;
  state.slip_speed = 0.0;
  EXPECT_NEAR(phase_axes(state).v_range, 1.15 * 0.4, 1e-12);
}

// The end card says what the run measured and why a guard stopped it.
TEST(RigOverlay, TheEndCardGivesThePeriodMuKAndTheStop) {
  RigOverlayState state;
  state.estimator.periods = 12;
  state.estimator.period = 0.7767;
  state.estimator.period_std = 0.0004;
  state.estimator.mu_k = 0.2896;
  state.estimator.mu_k_err = 0.011;
  state.regime = "oscillates";
  const TitleCard card = make_end_card(state, "theory: T = 0.7766 s", "");
  EXPECT_EQ(card.subtitle, "T = 0.7767 \xc2\xb1 0.0004 s  (N = 12)");
  ASSERT_GE(card.lines.size(), 3u);
  EXPECT_EQ(card.lines[0],
            "\xce\xbc\xe2\x82\x96 = 0.290 \xc2\xb1 0.011");  // a leading 1: two digits
  EXPECT_EQ(card.lines[1], "theory: T = 0.7766 s");
  const TitleCard stopped = make_end_card(state, "", "stopped at t = 1.200 s: the plate fell");
  EXPECT_EQ(stopped.lines.back(), "stopped at t = 1.200 s: the plate fell");
}

TEST(RigModel, PosesInterpolatePartByPart) {
  RigPose a;
  a.plate_x = 0.01;
  a.pitch = 0.002;
  a.shaft_angles = {1.0, -1.0};
  a.shaft_speeds = {100.0, -100.0};
  RigPose b = a;
  b.plate_x = 0.03;
  b.pitch = 0.004;
  b.shaft_angles = {1.2, -1.2};
  const RigPose m = interpolate(a, b, 0.25);
  EXPECT_DOUBLE_EQ(m.plate_x, 0.015);
  EXPECT_DOUBLE_EQ(m.pitch, 0.0025);
  EXPECT_DOUBLE_EQ(m.shaft_angles[0], 1.05);
  EXPECT_DOUBLE_EQ(m.shaft_angles[1], -1.05);
  // The plate's body frame: its centre of mass at the pose, pitched about +y.
  const Eigen::Affine3f t = plate_transform(b);
  EXPECT_NEAR((t * Eigen::Vector3f(0.1f, 0, 0)).z(), -0.1f * std::sin(0.004f), 1e-7);
}

// The frames show a value with its uncertainty by the lab's one rule (io/plus_minus.hpp, whose
// cases tests/io/plus_minus_test.cpp and the page's test share), with the font's "±", and a value
// without a spread alone, never "± 0".
TEST(RigOverlay, ValuesCarryTheirUncertaintysDigitsByTheLabsRule) {
  RigOverlayState state;
  state.has_sensor = true;
  EstimatorValues& e = state.estimator;
  e.periods = 5;
  e.period = 0.79412;
  e.period_std = 0.0012;
  e.mu_k = 0.2856;
  e.mu_k_err = 0.031;
  ResultsText text = results_text(state);
  EXPECT_EQ(text.period, "T = 0.7941 \xc2\xb1 0.0012 s");
  EXPECT_EQ(text.detail, "\xce\xbc\xe2\x82\x96 = 0.29 \xc2\xb1 0.03");
  e.period_std = 0.0062;
  EXPECT_EQ(results_text(state).period, "T = 0.794 \xc2\xb1 0.006 s");
  // One period: no spread to show.
  e.periods = 1;
  e.mu_k_err.reset();
  text = results_text(state);
  EXPECT_EQ(text.period, "T = 0.794 s");
  EXPECT_EQ(text.detail, "\xce\xbc\xe2\x82\x96 = 0.286");
}

TEST(RigOverlay, TheTitleCardNamesTheMaterialAndTheSetUp) {
  const TitleCard card = make_title_card(compile_rig(test::paper_rig()), "LEGO blocks", 4.0, 30);
  EXPECT_EQ(card.title, "The friction (Timoshenko) oscillator");
  EXPECT_EQ(card.subtitle, "LEGO blocks on PVC rollers, 300 K");
  // run --title replaces the title and nothing else.
  const TitleCard titled =
      make_title_card(compile_rig(test::paper_rig()), "LEGO blocks", 4.0, 30, "Friction at 77 K");
  EXPECT_EQ(titled.title, "Friction at 77 K");
  EXPECT_EQ(titled.subtitle, card.subtitle);
  EXPECT_EQ(titled.lines, card.lines);
  std::string all;
  for (const std::string& line : card.lines) all += line + "\n";
  for (const char* text : {"l = 89 mm", "1600 rpm", "8:1 gearbox", "4 LEGO bricks", "2 magnets",
                           "x = 114 mm", "T = 0.79 \xc2\xb1 0.03 s"})
    EXPECT_NE(all.find(text), std::string::npos) << text << " in\n" << all;
  EXPECT_NE(card.footer.find("slow motion \xc3\x97"
                             "4"),
            std::string::npos)
      << card.footer;
}

// What the results panel says as the estimator goes: learning the signal, waiting for pulses, a
// provisional period from the timed pulses, then the estimator's own, with N.
TEST(RigOverlay, TheResultsSayWhatIsMeasuredOrAwaited) {
  RigOverlayState state;
  EstimatorValues& e = state.estimator;
  auto text = results_text(state);
  EXPECT_EQ(text.period, "T: measuring\xe2\x80\xa6");
  EXPECT_EQ(text.detail, "learning the signal from its first pulses");
  EXPECT_EQ(text.paper, "(no paper value for this material)");
  // Learned from two pulses (marked on the plot), none timed yet.
  e.signal_learned = true;
  e.learning_pulses = 2;
  text = results_text(state);
  EXPECT_EQ(text.detail, "2 pulses seen, 0 timed (green): a first T at 2 timed");
  e.pulses = 1;
  text = results_text(state);
  EXPECT_EQ(text.detail, "3 pulses seen, 1 timed (green): a first T at 2 timed");
  // Two timed pulses: one period, shown alone (no spread to show, never "± 0").
  e.pulses = 2;
  e.provisional_periods = 1;
  e.provisional_period = 0.77661;
  text = results_text(state);
  EXPECT_EQ(text.period, "T \xe2\x89\x88 0.777 s");
  EXPECT_EQ(text.note, "(N = 1)");
  EXPECT_EQ(text.detail, "provisional until 5 timed pulses");
  EXPECT_EQ(text.period.find("\xc2\xb1"), std::string::npos);
  // Two periods: their spread.
  e.pulses = 3;
  e.provisional_periods = 2;
  e.provisional_period = 0.7766;
  e.provisional_std = 0.0004;
  text = results_text(state);
  EXPECT_EQ(text.period, "T \xe2\x89\x88 0.7766 \xc2\xb1 0.0004 s");
  EXPECT_EQ(text.note, "(N = 2)");
  // The estimator's own: one period alone, then several with their spread, and mu_k.
  e.geometry_known = true;
  e.periods = 1;
  e.period = 0.7767;
  e.period_std = 0.0;
  e.mu_k = 0.2968;
  e.mu_k_err = 0.0067;
  text = results_text(state);
  EXPECT_EQ(text.period, "T = 0.777 s");
  EXPECT_EQ(text.note, "(N = 1)");
  EXPECT_EQ(text.detail, "\xce\xbc\xe2\x82\x96 = 0.297 \xc2\xb1 0.007");
  e.periods = 4;
  e.period_std = 0.00017;
  e.periods_discarded = 1;
  text = results_text(state);
  EXPECT_EQ(text.period, "T = 0.77670 \xc2\xb1 0.00017 s");  // to its uncertainty's digits
  EXPECT_EQ(text.note, "(N = 4, 1 discarded)");
  // Geometry known but every period refused so far.
  e.periods = 0;
  e.period.reset();
  e.provisional_period.reset();
  e.provisional_periods = 0;
  text = results_text(state);
  EXPECT_EQ(text.period, "T: measuring\xe2\x80\xa6");
  EXPECT_EQ(text.detail, "5 pulses seen; no period has passed the checks yet");
  state.has_sensor = false;
  EXPECT_EQ(results_text(state).period, "no sensor: no period measured");
}

TEST(RigOverlay, TheHallPlotsAxesCarryValues) {
  const auto labels = [](const std::vector<AxisTick>& ticks) {
    std::string out;
    for (const AxisTick& t : ticks) out += t.label + " ";
    return out;
  };
  // The last 2.5 s at t = 3.2 s: every 0.5 s; none before the run's start.
  EXPECT_EQ(labels(hall_time_ticks(0.7, 3.2)), "1.0 1.5 2.0 2.5 3.0 ");
  EXPECT_EQ(labels(hall_time_ticks(-2.5, 0.6)), "0.0 0.5 ");
  EXPECT_EQ(labels(hall_time_ticks(0.0, 10.0)), "0.0 1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0 10.0 ");
  // Counts: 1, 2 or 5 times a power of ten, inside the range.
  EXPECT_EQ(labels(value_ticks(474.0, 746.0)), "500 600 700 ");
  EXPECT_EQ(labels(value_ticks(492.0, 532.0)), "500 510 520 530 ");
  EXPECT_EQ(labels(value_ticks(0.0, 1023.0)), "0 500 1000 ");
  // Millimetres of a small swing: steps below one keep their decimals.
  EXPECT_EQ(labels(value_ticks(-0.6, 0.6)), "-0.5 0 0.5 ");
  EXPECT_TRUE(value_ticks(5.0, 5.0).empty());
}

TEST(RigOverlay, TheTopBarNamesTheTemperatureTheSceneSets) {
  Scene scene = test::paper_rig();
  EXPECT_EQ(rig_heading(compile_rig(scene), "LEGO blocks"),
            "LEGO blocks on PVC rollers  \xc2\xb7  300 K  \xc2\xb7  l = 89 mm");
  scene.friction.temperature = 77.0;
  EXPECT_EQ(rig_heading(compile_rig(scene), "LEGO blocks"),
            "LEGO blocks on PVC rollers  \xc2\xb7  77 K  \xc2\xb7  l = 89 mm");
  scene.friction.warming = WarmingDesc{};
  EXPECT_EQ(rig_heading(compile_rig(scene), "LEGO blocks"),
            "LEGO blocks on PVC rollers  \xc2\xb7  from 77 K  \xc2\xb7  l = 89 mm");
  scene.friction.temperature_set = false;  // a scene that names none
  EXPECT_EQ(rig_heading(compile_rig(scene), "LEGO blocks"),
            "LEGO blocks on PVC rollers  \xc2\xb7  l = 89 mm");
  scene.world.tilt = -2.0 * kPi / 180.0;  // a tilted rig says so
  EXPECT_EQ(rig_heading(compile_rig(scene), "LEGO blocks"),
            "LEGO blocks on PVC rollers  \xc2\xb7  l = 89 mm  \xc2\xb7  tilted -2.0\xc2\xb0");
}

// A tilted rig is drawn tilted: the model turns the rig's frame about y so that +x rises by the
// tilt, and the force arrows start where the turned plate's points are.
TEST(RigOverlay, ATiltedRigIsDrawnTilted) {
  Scene scene = test::scene_file("minimal.yaml");
  scene.world.tilt = 3.0 * kPi / 180.0;
  const RigModel model = build_rig_model(compile_rig(scene), nullptr, nullptr);
  const Eigen::Vector3f end = model.tilt * Eigen::Vector3f(0.1f, 0.0f, 0.0f);
  EXPECT_NEAR(std::atan2(end.z(), end.x()), 3.0 * kPi / 180.0, 1e-6);
  // The normal force's arrow stands on the turned plate: along the rig's z turned the same way.
  PlateForces forces;
  forces.rig_to_world = model.tilt;
  forces.rollers[0] = ContactForce{true, 1.0, 0.0, Eigen::Vector3f(-0.0445f, 0.0f, 0.0f)};
  VideoDesc video;
  video.width = 640;
  video.height = 360;
  const Camera camera = rig_camera(model, video);
  const ForceScale scale{100.0f, 1.0};
  const std::vector<ForceArrow> arrows = force_arrows(camera, 640, 360, forces, scale);
  ASSERT_EQ(arrows.size(), 3u);  // F0, the net friction (both zero) and N0, last
  const ForceArrow& n0 = arrows.back();
  // Where the turned contact point and a point 1 N along the turned normal project.
  const auto projected = [&](const Eigen::Vector3f& p) {
    return *project_to_pixel(camera, 640, 360, p);
  };
  const Eigen::Vector3f from = model.tilt * Eigen::Vector3f(-0.0445f, 0.0f, 0.0f);
  EXPECT_LT((n0.from - projected(from)).norm(), 1e-3f);
  const Eigen::Vector2f direction = (n0.to - n0.from).normalized();
  const Eigen::Vector2f expected =
      (projected(from + 0.01f * (model.tilt.linear() * Eigen::Vector3f::UnitZ())) - n0.from)
          .normalized();
  EXPECT_GT(direction.dot(expected), 0.9999f);
}

// The file's extension picks the format; a GIF is drawn small unless asked otherwise.
TEST(VideoFormat, TheExtensionPicksTheFormatAndAnyOtherIsRefused) {
  EXPECT_EQ(video_format_of("out/rig.mp4"), VideoFormat::kMp4);
  EXPECT_EQ(video_format_of("RIG.GIF"), VideoFormat::kGif);
  EXPECT_EQ(video_format_of("a.b/rig.webm"), VideoFormat::kWebm);
  EXPECT_FALSE(video_format_of("rig.avi"));
  EXPECT_FALSE(video_format_of("mp4"));
  EXPECT_FALSE(video_format_of("out.mp4/rig"));
  EXPECT_EQ(video_file_problem("rig.mp4"), "");
  EXPECT_NE(video_file_problem("rig.avi").find("expected a video file ending in .mp4, .gif or "
                                               ".webm"),
            std::string::npos);
  Scene scene = test::paper_rig();  // 1280x720 at 30 fps
  VideoRequest request;
  request.video = "rig.gif";
  VideoDesc v = effective_video(scene, request);
  EXPECT_EQ(v.width, kGifMaxWidth);
  EXPECT_EQ(v.height, kGifMaxHeight);
  EXPECT_EQ(v.fps, kGifMaxFps);
  request.size = std::array<int, 2>{320, 180};
  request.fps = 20;
  v = effective_video(scene, request);
  EXPECT_EQ(v.width, 320);
  EXPECT_EQ(v.fps, 20);
  request.video = "rig.mp4";
  request.size.reset();
  request.fps.reset();
  v = effective_video(scene, request);
  EXPECT_EQ(v.width, 1280);
  EXPECT_EQ(v.fps, 30);
  request.video = "rig.avi";
  EXPECT_THROW(effective_video(scene, request), InputError);
}

TEST(VideoClock, FramesFollowTheVideosClock) {
  VideoDesc v;
  EXPECT_EQ(run_frame_count(v, 10.0), 300u);  // 10 s at 30 fps, t = 0 included, t = 10 s not
  v.slow_motion = 4.0;
  EXPECT_EQ(run_frame_count(v, 10.0), 1200u);
  v.slow_motion = 0.5;
  EXPECT_EQ(run_frame_count(v, 1.0), 15u);
  v.slow_motion = 0.35;  // 10.5 frames a simulated second: t_k < 1 s for k = 0 .. 10
  EXPECT_EQ(run_frame_count(v, 1.0), 11u);
  v.fps = 24;
  v.slow_motion = 1.0;
  EXPECT_EQ(run_frame_count(v, 0.001), 1u);
  EXPECT_EQ(title_frame_count(v), 0u);
  v.title = true;
  EXPECT_EQ(title_frame_count(v), 48u);
}

TEST(VideoClock, TheCommandLineOverridesTheScene) {
  Scene scene = test::paper_rig();
  VideoRequest request;
  VideoDesc v = effective_video(scene, request);
  EXPECT_EQ(v.width, 1280);
  EXPECT_EQ(v.camera, "front");
  EXPECT_TRUE(v.title);
  request.size = std::array<int, 2>{640, 360};
  request.fps = 24;
  request.slow_motion = 2.5;
  request.camera = "sensor";
  v = effective_video(scene, request);
  EXPECT_EQ(v.width, 640);
  EXPECT_EQ(v.height, 360);
  EXPECT_EQ(v.fps, 24);
  EXPECT_DOUBLE_EQ(v.slow_motion, 2.5);
  EXPECT_EQ(v.camera, "sensor");
  const auto message = [&](const VideoRequest& r) { return request_error(scene, r); };
  VideoRequest odd;
  odd.size = std::array<int, 2>{641, 360};
  EXPECT_NE(message(odd).find("--size: error: H.264 in yuv420p needs an even width and height"),
            std::string::npos)
      << message(odd);
  VideoRequest camera;
  camera.camera = "side";
  EXPECT_NE(message(camera).find("--camera"), std::string::npos);
  EXPECT_NE(message(camera).find("found \"side\""), std::string::npos);
  VideoRequest fps;
  fps.fps = 0;
  EXPECT_NE(message(fps).find("--fps"), std::string::npos);
  VideoRequest slow;
  slow.slow_motion = 0.0;
  EXPECT_NE(message(slow).find("--slow-motion"), std::string::npos);
}

// --orbit, --title and --captions: the orbit in rad per second of video and checked as the
// scene's, a title that turns the card on, captions that replace the scene's (none: off).
TEST(VideoClock, TheOrbitTitleAndCaptionsFromTheCommandLine) {
  Scene scene = test::paper_rig();
  scene.video->title = false;
  scene.video->captions = {{0.0, std::nullopt, "the scene's"}};
  VideoRequest request;
  VideoDesc v = effective_video(scene, request);
  EXPECT_EQ(v.orbit, 0.0);
  EXPECT_FALSE(v.title);
  EXPECT_TRUE(v.title_text.empty());
  ASSERT_EQ(v.captions.size(), 1u);
  request.orbit = 10.0 * kPi / 180.0;
  request.title = "Friction at 77 K";
  request.captions = std::vector<Caption>{{1.0, 2.0, "one"}, {3.0, std::nullopt, "two"}};
  v = effective_video(scene, request);
  EXPECT_NEAR(v.orbit, 10.0 * kPi / 180.0, 1e-15);
  EXPECT_TRUE(v.title);
  EXPECT_EQ(v.title_text, "Friction at 77 K");
  ASSERT_EQ(v.captions.size(), 2u);
  EXPECT_EQ(v.captions[1].text, "two");
  EXPECT_EQ(title_frame_count(v), 60u);  // the card is on: 2 s at 30 fps
  request.captions = std::vector<Caption>{};
  EXPECT_TRUE(effective_video(scene, request).captions.empty());
  const auto message = [&](const VideoRequest& r) { return request_error(scene, r); };
  VideoRequest fast;
  fast.orbit = 7.0;  // rad/s, over 360 deg/s
  EXPECT_NE(message(fast).find("--orbit: error: expected an orbit of at most 360 deg/s"),
            std::string::npos)
      << message(fast);
  VideoRequest blank;
  blank.title = "  ";
  EXPECT_NE(message(blank).find("--title: error: expected the title card's title"),
            std::string::npos)
      << message(blank);
}

// A scene with a `video` part, as the loader reads it.
Scene with_video(const std::string& video) {
  const std::string text =
      "format: 1\n"
      "rollers: {spacing: 89 mm, radius: 10 mm}\n"
      "plate: {length: 200 mm, thickness: 5 mm, offset: 20 mm}\n"
      "friction: {mu_k: 0.3}\n"
      "video:\n" +
      video;
  return load_scene_text(text, "v.yaml", {},
                         []() -> const PaperTable& { return test::paper_table(); });
}

std::string video_error(const std::string& video) {
  try {
    with_video(video);
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

TEST(VideoKeys, AreReadWithTheirUnitsAndDefaults) {
  const Scene none = test::scene_file("minimal.yaml");
  EXPECT_FALSE(none.video.has_value());
  const Scene s = with_video(
      "  size: 640x360\n  fps: 24\n  slow_motion: 4\n  camera: top\n  orbit: 6 deg/s\n"
      "  title: true\n");
  ASSERT_TRUE(s.video.has_value());
  EXPECT_EQ(s.video->width, 640);
  EXPECT_EQ(s.video->height, 360);
  EXPECT_EQ(s.video->fps, 24);
  EXPECT_DOUBLE_EQ(s.video->slow_motion, 4.0);
  EXPECT_EQ(s.video->camera, "top");
  EXPECT_NEAR(s.video->orbit, 6.0 * kPi / 180.0, 1e-12);
  EXPECT_TRUE(s.video->title);
  const Scene d = with_video("  size: [320, 180]\n");
  EXPECT_EQ(d.video->width, 320);
  EXPECT_EQ(d.video->fps, 30);
  EXPECT_DOUBLE_EQ(d.video->slow_motion, 1.0);
  EXPECT_EQ(d.video->camera, "front");
  EXPECT_FALSE(d.video->title);
  EXPECT_FALSE(d.video->phase_portrait);
  EXPECT_TRUE(with_video("  phase_portrait: true\n").video->phase_portrait);
  const Scene placed =
      with_video("  camera: {position: [0.1 m, -0.3 m, 0.2 m], target: [0, 0, 0], fov: 25 deg}\n");
  ASSERT_TRUE(placed.video->placed.has_value());
  EXPECT_DOUBLE_EQ(placed.video->placed->position[1], -0.3);
  EXPECT_NEAR(placed.video->placed->fov, 25.0 * kPi / 180.0, 1e-12);
  EXPECT_TRUE(placed.video->camera.empty());
  // The paper's rig asks for a title card at 720p.
  ASSERT_TRUE(test::paper_rig().video.has_value());
  EXPECT_TRUE(test::paper_rig().video->title);
}

TEST(VideoKeys, MistakesAreLocatedErrors) {
  EXPECT_NE(video_error("  sise: 640x360\n").find("v.yaml:6:3: error: video"), std::string::npos)
      << video_error("  sise: 640x360\n");
  EXPECT_NE(video_error("  sise: 640x360\n").find("did you mean 'size'"), std::string::npos);
  EXPECT_NE(video_error("  size: 641x360\n").find("v.yaml:6:9: error: video.size: H.264"),
            std::string::npos)
      << video_error("  size: 641x360\n");
  EXPECT_NE(video_error("  size: big\n").find("expected a frame size like \"1280x720\""),
            std::string::npos);
  EXPECT_NE(video_error("  camera: side\n")
                .find("v.yaml:6:11: error: video.camera: expected a "
                      "camera preset (front, top, sensor, phone)"),
            std::string::npos)
      << video_error("  camera: side\n");
  EXPECT_NE(video_error("  camera: {position: [0, 0, 1], target: [0, 0, 0], fov: 170 deg}\n")
                .find("from 5 deg to 120 deg"),
            std::string::npos);
  EXPECT_NE(video_error("  camera: {position: [0, 0, 1]}\n").find("'target'"), std::string::npos)
      << video_error("  camera: {position: [0, 0, 1]}\n");
  EXPECT_NE(video_error("  fps: 0\n").find("1 to 240 frames per second"), std::string::npos);
  EXPECT_NE(video_error("  slow_motion: 0\n").find("slow-motion factor"), std::string::npos);
  EXPECT_NE(video_error("  orbit: 5 mm\n").find("video.orbit"), std::string::npos)
      << video_error("  orbit: 5 mm\n");
  EXPECT_NE(video_error("  title: maybe\n").find("expected true or false"), std::string::npos);
  EXPECT_NE(video_error("  phase_portrait: yes please\n").find("video.phase_portrait"),
            std::string::npos)
      << video_error("  phase_portrait: yes please\n");
}

}  // namespace
}  // namespace fl::render
