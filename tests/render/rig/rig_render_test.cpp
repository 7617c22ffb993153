// The paper's rig drawn on each GL back end (OSMesa, EGL): a frame is not blank, the plate's pixels
// lie where the projection of its pose says, two poses give two pictures, the overlay's text shows,
// a caption shows as a subtitle clear of the bottom panels, and each camera preset matches its
// golden image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/gl/renderer.hpp"
#include "render/rig/caption_overlay.hpp"
#include "render/rig/rig_camera.hpp"
#include "render/rig/rig_overlay.hpp"
#include "render/rig/rig_view.hpp"
#include "render_test_support.hpp"
#include "support/rig_fixture.hpp"

namespace fl::render {
namespace {

using test::paper_rig_model;

// The rig at a pose: the plate at x, the rollers turned.
RigPose pose_at(double plate_x, double roller_angle) {
  RigPose pose = rest_pose(compile_rig(test::paper_rig()));
  pose.plate_x = plate_x;
  pose.shaft_angles[0] = roller_angle;
  pose.shaft_angles[1] = -roller_angle;
  return pose;
}

Image draw(Renderer& renderer, const RigView& view, const Camera& camera, const RigPose& pose) {
  renderer.begin_frame(camera, rig_light());
  view.draw(pose, 0.0);
  return copy_image(renderer.end_frame());
}

struct Centroid {
  double x = 0;
  double y = 0;
  std::size_t pixels = 0;
};

// The centre of the pixels where two frames differ.
Centroid difference_centroid(const ImageView& a, const ImageView& b) {
  Centroid c;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      int change = 0;
      for (std::size_t k = 0; k < 3; ++k) change += std::abs(a.at(x, y)[k] - b.at(x, y)[k]);
      if (change <= 24) continue;
      c.x += x + 0.5;
      c.y += y + 0.5;
      ++c.pixels;
    }
  }
  if (c.pixels > 0) {
    c.x /= static_cast<double>(c.pixels);
    c.y /= static_cast<double>(c.pixels);
  }
  return c;
}

// Each test on each GL back end.
class RigRender : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    FL_REQUIRE_BACKEND(GetParam());
    if (!assets::kHasAssets) GTEST_SKIP() << "built without FRICTIONLAB_WITH_ASSETS (assimp)";
  }
};

TEST_P(RigRender, TheRigIsDrawnAndThePlateLandsWhereItsPoseSays) {
  constexpr int kWidth = 480;
  constexpr int kHeight = 270;
  const auto context = test::gl_context(GetParam(), kWidth, kHeight);
  // No shadows: the plate's silhouette is then all that changes when it is left out.
  RendererOptions options;
  options.shadows = false;
  Renderer renderer(*context, options);
  const RigModel model = paper_rig_model();
  RigModel without_plate = model;
  std::erase_if(without_plate.parts,
                [](const RigPart& p) { return p.body == RigPart::Body::kPlate; });
  const RigView view(renderer, model);
  const RigView empty(renderer, without_plate);
  VideoDesc video;
  video.width = kWidth;
  video.height = kHeight;
  video.camera = "top";
  const Camera camera = rig_camera(model, video);

  const PlateMass mass = plate_mass(test::paper_rig());
  const PlateDesc& plate = test::paper_rig().plate;
  for (const double x : {-0.025, 0.0, 0.02}) {
    const RigPose pose = pose_at(x, 0.3);
    const Image with = draw(renderer, view, camera, pose);
    const Image without = draw(renderer, empty, camera, pose);
    fl::test::keep_frame("rig_top_" + std::to_string(static_cast<int>(x * 1000)), with.view());
    // Not blank: the rig covers a good part of the frame, in many colours.
    EXPECT_GT(count_pixels_unlike(with.view(), {237, 240, 245}, 12),
              static_cast<std::size_t>(kWidth * kHeight / 2));
    // The plate's silhouette (slab, blocks, magnets) is centred on the projection of the centre
    // of its top face (the blocks stand symmetrically on it).
    const Centroid c = difference_centroid(with.view(), without.view());
    const Eigen::Vector3f top_centre =
        plate_transform(pose) * Eigen::Vector3f(static_cast<float>(-mass.x_c), 0.0f,
                                                static_cast<float>(plate.thickness - mass.h_c));
    const auto expected = project_to_pixel(camera, kWidth, kHeight, top_centre);
    ASSERT_TRUE(expected.has_value());
    ASSERT_GT(c.pixels, 2000u) << "the plate is missing at x = " << x;
    EXPECT_NEAR(c.x, expected->x(), 3.0) << "plate at x = " << x;
    EXPECT_NEAR(c.y, expected->y(), 3.0) << "plate at x = " << x;
  }
}

// A GL context of a frame's size on a back end, its renderer, the paper's rig in it and the rig's
// camera for that frame.
struct Stage {
  Stage(const std::string& backend, int width, int height)
      : context(test::gl_context(backend, width, height)),
        renderer(*context),
        view(renderer, paper_rig_model()) {
    video.width = width;
    video.height = height;
    camera = rig_camera(view.model(), video);
  }
  std::unique_ptr<GlContext> context;
  Renderer renderer;
  const RigView view;
  VideoDesc video;
  Camera camera;
};

TEST_P(RigRender, PosesChangeTheFrameAndTheSamePoseDoesNot) {
  Stage stage(GetParam(), 320, 180);
  Renderer& renderer = stage.renderer;
  const RigView& view = stage.view;
  const Camera& camera = stage.camera;
  const Image a = draw(renderer, view, camera, pose_at(0.0, 0.0));
  const Image b = draw(renderer, view, camera, pose_at(0.02, 0.0));
  const Image c = draw(renderer, view, camera, pose_at(0.0, 1.2));
  const Image a_again = draw(renderer, view, camera, pose_at(0.0, 0.0));
  EXPECT_GT(rms_difference(a.view(), b.view()), 1.0);  // the plate moved
  EXPECT_GT(rms_difference(a.view(), c.view()), 0.1);  // the rollers' marks turned
  EXPECT_EQ(rms_difference(a.view(), a_again.view()), 0.0);
  // Moving the plate along +x moves it right in the front view.
  EXPECT_GT(difference_centroid(a.view(), b.view()).pixels, 200u);
}

TEST_P(RigRender, TheOverlayIsDrawnAtSixFortyByThreeSixty) {
  Stage stage(GetParam(), 640, 360);
  Renderer& renderer = stage.renderer;
  const RigView& view = stage.view;
  std::vector<HallPoint> hall;
  for (int k = 0; k < 2500; ++k) {
    const double t = 0.5 + k * 1e-3;
    hall.push_back({t, 512.0 + 300.0 * std::exp(-std::pow((std::fmod(t, 0.794) - 0.4) / 0.02, 2))});
  }
  const std::vector<double> pulses = {1.194, 1.988, 2.782};
  RigOverlayState state;
  state.heading = "LEGO blocks on PVC rollers  \xc2\xb7  l = 89 mm";
  state.t = 3.0;
  state.motor_speed = 20.7;
  state.roller_speed = 165.6;
  state.hall = hall;
  state.hall_range = std::array<double, 2>{480.0, 840.0};
  state.pulses = pulses;
  state.estimator.pulses = 4;
  state.estimator.periods = 3;
  state.estimator.period = 0.794;
  state.estimator.period_std = 0.006;
  state.estimator.mu_k = 0.285;
  state.estimator.mu_k_err = 0.008;
  state.paper_period = test::paper_rig().friction.paper_period;
  state.paper_mu_k = test::paper_rig().friction.paper_mu_k;
  renderer.begin_frame(stage.camera, rig_light());
  view.draw(pose_at(0.01, 0.5), 1.0 / 120.0);
  draw_rig_overlay(renderer.overlay(), 640, 360, state);
  const Image frame = copy_image(renderer.end_frame());
  fl::test::keep_frame("rig_overlay_640x360", frame.view());
  // The panels are dark, with light text on them: the top bar, the Hall plot, the results.
  const auto light_pixels = [&](int x0, int y0, int x1, int y1) {
    std::size_t n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) n += frame.at(x, y)[0] > 180 && frame.at(x, y)[2] > 180;
    return n;
  };
  EXPECT_GT(light_pixels(8, 4, 300, 18), 150u);       // the heading
  EXPECT_GT(light_pixels(372, 290, 620, 310), 150u);  // T = 0.794 ± 0.006 s
  // The trace is drawn in yellow inside the plot, and the pulses in green.
  std::size_t yellow = 0, green = 0;
  for (int y = 278; y < 350; ++y) {
    for (int x = 14; x < 302; ++x) {
      const auto p = frame.at(x, y);
      yellow += p[0] > 200 && p[1] > 150 && p[2] < 90;
      green += p[1] > 180 && p[0] < 150 && p[2] < 150;
    }
  }
  EXPECT_GT(yellow, 300u);
  EXPECT_GT(green, 30u);
}

// Where two frames differ: the bounding box of the pixels that changed.
struct Changed {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // x1, y1 past the last
  std::size_t pixels = 0;
};
Changed changed(const ImageView& a, const ImageView& b) {
  Changed c;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (std::size_t k = 0; k < 3; ++k)
        if (a.at(x, y)[k] != b.at(x, y)[k]) {
          c.x0 = std::min(c.x0, x);
          c.y0 = std::min(c.y0, y);
          c.x1 = std::max(c.x1, x + 1);
          c.y1 = std::max(c.y1, y + 1);
          ++c.pixels;
          break;
        }
  return c;
}

// At 640x360 (a GIF's size) nothing of the overlay runs past its panels: the Hall plot's last time
// label sits at the plot's right end, and a long line of the results shrinks to the panel's width
// instead of running to the frame's edge. The strips beside the panels are as the rig left them.
TEST_P(RigRender, TheOverlayStaysInsideItsPanelsAtSixFortyByThreeSixty) {
  Stage stage(GetParam(), 640, 360);
  Renderer& renderer = stage.renderer;
  const RigView& view = stage.view;
  const Camera& camera = stage.camera;
  std::vector<HallPoint> hall;
  for (int k = 0; k < 2500; ++k) hall.push_back({3.5 + k * 1e-3, 512.0});
  RigOverlayState state;
  state.heading = "LEGO blocks on PVC rollers";
  state.t = 6.0;  // the Hall window ends on a labelled tick: 6.0 at the plot's right end
  state.roller_speed = 165.6;
  state.hall = hall;
  state.estimator.signal_learned = true;
  state.estimator.learning_pulses = 40;  // "40 pulses seen, 0 timed ...": the longest line
  state.paper_period = test::paper_rig().friction.paper_period;
  state.paper_mu_k = test::paper_rig().friction.paper_mu_k;
  const auto frame = [&](bool overlay) {
    renderer.begin_frame(camera, rig_light());
    view.draw(pose_at(0.0, 0.0), 0.0);
    if (overlay) draw_rig_overlay(renderer.overlay(), 640, 360, state);
    return copy_image(renderer.end_frame());
  };
  const Image bare = frame(false);
  const Image drawn = frame(true);
  fl::test::keep_frame("rig_overlay_inside_panels", drawn.view());
  const auto same = [&](int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        for (std::size_t k = 0; k < 3; ++k)
          if (bare.at(x, y)[k] != drawn.at(x, y)[k]) return false;
    return true;
  };
  // The Hall plot's panel spans x 8 to 308 and y 256 to 352; the results' x 364 to 632, y 284 to
  // 352.
  EXPECT_TRUE(same(308, 256, 360, 352)) << "the Hall plot's labels run past its panel";
  EXPECT_TRUE(same(632, 284, 640, 352)) << "the results run past their panel";
  EXPECT_FALSE(same(364, 284, 632, 352));  // the results are drawn
}

// A caption at 640x360 over the rig and the overlay: a dark box with light text, centred above
// the Hall plot (its top at y = 256) and the results panel, which stay as they were; a long
// caption wraps to more lines within the same width, three at most.
TEST_P(RigRender, ACaptionIsASubtitleClearOfTheBottomPanels) {
  Stage stage(GetParam(), 640, 360);
  Renderer& renderer = stage.renderer;
  const RigView& view = stage.view;
  std::vector<HallPoint> hall;
  for (int k = 0; k < 2500; ++k)
    hall.push_back({0.5 + k * 1e-3, 512.0 + 200.0 * std::sin(k * 0.01)});
  RigOverlayState state;
  state.heading = "LEGO blocks on PVC rollers";
  state.t = 3.0;
  state.hall = hall;
  state.estimator.pulses = 3;
  const auto frame = [&](const std::string& caption) {
    renderer.begin_frame(stage.camera, rig_light());
    view.draw(pose_at(0.01, 0.5), 0.0);
    draw_rig_overlay(renderer.overlay(), 640, 360, state);
    if (!caption.empty()) draw_caption(renderer.overlay(), 640, 360, caption);
    return copy_image(renderer.end_frame());
  };
  const Image none = frame("");
  const std::string short_text = "The rollers turn toward each other at 1600 rpm.";
  const std::string long_text =
      "When the plate moves toward one roller, that roller carries more of its weight, its "
      "friction is the larger, and the net friction pulls the plate back to the middle: a "
      "harmonic oscillator with \xcf\x89\xc2\xb2 = 2\xce\xbc\xe2\x82\x96g/l.";
  const Image one = frame(short_text);
  const Image many = frame(long_text);
  fl::test::keep_frame("rig_caption_" + GetParam(), many.view());
  const Changed a = changed(none.view(), one.view());
  const Changed b = changed(none.view(), many.view());
  for (const Changed& c : {a, b}) {
    ASSERT_GT(c.pixels, 1000u);
    EXPECT_LE(c.y1, 256);                          // above the Hall plot and the results panel
    EXPECT_GT(c.y0, 100);                          // in the frame's lower half, near the panels
    EXPECT_NEAR(0.5 * (c.x0 + c.x1), 320.0, 2.0);  // centred
    EXPECT_GT(c.x0, 40);                           // within the frame's width, with a margin
    EXPECT_LT(c.x1, 600);
  }
  // The long one wraps: taller, at least twice the short one's single line, and wider.
  EXPECT_GT(b.y1 - b.y0, 2 * (a.y1 - a.y0) - 4);
  EXPECT_GT(b.x1 - b.x0, a.x1 - a.x0);
  EXPECT_LE(layout_caption(renderer.overlay(), 640, 360, long_text).lines.size(), 3u);
  // Dark behind light text: in the short caption's box most pixels are darker than without it,
  // and some are near white where there were none.
  std::size_t darker = 0, white = 0, white_before = 0, inside = 0;
  for (int y = a.y0; y < a.y1; ++y)
    for (int x = a.x0; x < a.x1; ++x) {
      const auto p = one.at(x, y);
      const auto q = none.at(x, y);
      darker += p[0] + p[1] + p[2] < q[0] + q[1] + q[2];
      white += p[0] > 220 && p[1] > 220 && p[2] > 200;
      white_before += q[0] > 220 && q[1] > 220 && q[2] > 200;
      ++inside;
    }
  EXPECT_GT(darker, inside / 2);
  EXPECT_GT(white, white_before + 100);
}

// Each camera preset at 160x90, the rig at a fixed pose (no overlay), against
// tests/render/golden/rig_<preset>_160x90.png. Refresh on purpose, after a deliberate change of
// the look, with FRICTIONLAB_UPDATE_GOLDEN=1, and look at the new PNGs before committing them.
TEST_P(RigRender, EachCameraPresetMatchesItsGoldenImage) {
  const auto context = test::gl_context(GetParam(), 160, 90);
  Renderer renderer(*context);
  const RigView view(renderer, paper_rig_model());
  // The front camera's videos cut the near wall away.
  const RigView cutaway(renderer, paper_rig_model(true));
  RigPose pose = pose_at(0.012, 0.4);
  for (std::size_t s = 2; s < pose.shaft_angles.size(); ++s) pose.shaft_angles[s] = 0.1 * s;
  const char* update = std::getenv("FRICTIONLAB_UPDATE_GOLDEN");
  for (const std::string_view preset : kCameraPresets) {
    VideoDesc video;
    video.width = 160;
    video.height = 90;
    video.camera = std::string(preset);
    const RigView& shown = preset == "front" ? cutaway : view;
    const Image frame = draw(renderer, shown, rig_camera(shown.model(), video), pose);
    const std::string name = "rig_" + std::string(preset) + "_160x90";
    const std::string kept = name + "_" + GetParam();
    const std::string golden =
        std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/render/golden/" + name + ".png";
    if (update != nullptr && std::string(update) == "1") {
      write_png(golden, frame.view());
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(golden))
        << golden << " is missing; make it with FRICTIONLAB_UPDATE_GOLDEN=1";
    const Image expected = read_png(golden);
    const double rms = rms_difference(frame.view(), expected.view());
    constexpr double kTolerance = 3.0;  // as the demo scene's golden image
    if (rms > kTolerance) {
      fl::test::keep_frame(kept + "_actual", frame.view());
      fl::test::keep_frame(kept + "_difference",
                           difference_image(frame.view(), expected.view()).view());
    }
    EXPECT_LE(rms, kTolerance) << preset << ": RMS difference " << rms
                               << " from the golden image; see render-test-output/" << kept
                               << "_actual.png and _difference.png in the build folder";
  }
  if (update != nullptr && std::string(update) == "1") GTEST_SKIP() << "wrote the golden images";
}

// The title card at full strength hides the panels drawn before it: where the results panel and
// the speeds' panel are, the card shows its own colour, as where no panel is.
TEST_P(RigRender, TheTitleCardIsOpaque) {
  Stage stage(GetParam(), 640, 360);
  Renderer& renderer = stage.renderer;
  const RigView& view = stage.view;
  RigOverlayState state;
  state.heading = "LEGO blocks on PVC rollers";
  state.estimator.pulses = 2;
  const TitleCard card = make_title_card(compile_rig(test::paper_rig()), "LEGO blocks", 1.0, 30);
  renderer.begin_frame(stage.camera, rig_light());
  view.draw(pose_at(0.0, 0.0), 0.0);
  draw_rig_overlay(renderer.overlay(), 640, 360, state);
  draw_title_card(renderer.overlay(), 640, 360, card, 1.0f);
  const Image frame = copy_image(renderer.end_frame());
  fl::test::keep_frame("rig_title_card_" + GetParam(), frame.view());
  // A pixel of the card over no panel (and over the rig), and over the panels' corners.
  const auto card_colour = frame.at(320, 250);
  for (const auto& [x, y] : {std::pair{630, 352}, std::pair{12, 32}, std::pair{12, 352},
                             std::pair{400, 250}, std::pair{20, 180}})
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(frame.at(x, y)[k], card_colour[k]) << "at " << x << ", " << y;
}

INSTANTIATE_TEST_SUITE_P(BackEnds, RigRender, ::testing::ValuesIn(test::kGlBackends),
                         test::backend_test_name);

}  // namespace
}  // namespace fl::render
