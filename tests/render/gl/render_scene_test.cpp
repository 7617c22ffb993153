// The drawing layer on each GL back end (OSMesa, EGL): a box lands where its projection says, poses
// change the frame, frames are never blank, text and shapes land in their boxes, and the demo scene
// matches its golden image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/demo_scene.hpp"
#include "render/gl/gl_api.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/renderer.hpp"
#include "render/gl/shader.hpp"
#include "render_test_support.hpp"

namespace fl::render {
namespace {

// The default background, (0.93, 0.94, 0.96) in 8 bits.
constexpr std::array<std::uint8_t, 3> kBackground = {237, 240, 245};

struct Centroid {
  double x = 0;
  double y = 0;
  std::size_t pixels = 0;
};

// The centre of the pixels that differ from the background.
Centroid foreground_centroid(const ImageView& frame) {
  Centroid c;
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      const auto p = frame.at(x, y);
      bool differs = false;
      for (int k = 0; k < 3; ++k) {
        differs = differs || std::abs(p[static_cast<std::size_t>(k)] -
                                      kBackground[static_cast<std::size_t>(k)]) > 12;
      }
      if (!differs) continue;
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
class RenderScene : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    FL_REQUIRE_BACKEND(GetParam());
    context_ = test::gl_context(GetParam(), kWidth, kHeight);
    renderer_ = std::make_unique<Renderer>(*context_);
    camera_.position = Eigen::Vector3f(0.05f, -0.45f, 0.20f);
    camera_.target = Eigen::Vector3f(0.0f, 0.0f, 0.0f);
    camera_.fov_y_degrees = 35.0f;
  }

  // One box of 4 cm at `centre`, turned by `yaw` about z.
  Image draw_box(const Eigen::Vector3f& centre, float yaw) {
    if (box_ == kNoMesh)
      box_ =
          renderer_->upload(make_box(Eigen::Vector3f::Constant(0.04f), Color{0.8f, 0.15f, 0.1f}));
    renderer_->begin_frame(camera_, DirectionalLight{});
    Eigen::Affine3f pose = Eigen::Affine3f::Identity();
    pose.translate(centre);
    pose.rotate(Eigen::AngleAxisf(yaw, Eigen::Vector3f::UnitZ()));
    renderer_->draw(box_, pose);
    return copy_image(renderer_->end_frame());
  }

  static constexpr int kWidth = 320;
  static constexpr int kHeight = 180;
  static constexpr MeshId kNoMesh = ~MeshId{0};
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<Renderer> renderer_;
  Camera camera_;
  MeshId box_ = kNoMesh;
};

TEST_P(RenderScene, ABoxLandsWhereItsProjectionSays) {
  for (const Eigen::Vector3f& centre :
       {Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(0.08f, 0.02f, 0.04f),
        Eigen::Vector3f(-0.10f, -0.05f, -0.03f)}) {
    const Image frame = draw_box(centre, 0.3f);
    const Centroid c = foreground_centroid(frame.view());
    const auto expected = project_to_pixel(camera_, kWidth, kHeight, centre);
    ASSERT_TRUE(expected.has_value());
    ASSERT_GT(c.pixels, 200u) << "the box is missing at " << centre.transpose();
    // The silhouette's centroid and the projected centre differ by perspective only.
    EXPECT_NEAR(c.x, expected->x(), 2.0) << centre.transpose();
    EXPECT_NEAR(c.y, expected->y(), 2.0) << centre.transpose();
  }
}

TEST_P(RenderScene, TwoPosesGiveDifferentFrames) {
  const Image a = draw_box(Eigen::Vector3f(0.0f, 0.0f, 0.0f), 0.0f);
  const Image b = draw_box(Eigen::Vector3f(0.0f, 0.0f, 0.0f), 0.4f);
  const Image c = draw_box(Eigen::Vector3f(0.03f, 0.0f, 0.0f), 0.0f);
  const Image a_again = draw_box(Eigen::Vector3f(0.0f, 0.0f, 0.0f), 0.0f);
  EXPECT_GT(rms_difference(a.view(), b.view()), 1.0);
  EXPECT_GT(rms_difference(a.view(), c.view()), 1.0);
  // Moving along +x moves the box right in the picture.
  EXPECT_GT(foreground_centroid(c.view()).x, foreground_centroid(a.view()).x + 10.0);
  // The same pose draws the same frame.
  EXPECT_EQ(rms_difference(a.view(), a_again.view()), 0.0);
}

// A stream of frames read back behind the drawing (pixel buffer objects on EGL, OSMesa's own
// buffer at once) comes out in the order it was drawn, each frame the pixels end_frame gives for
// the same pose.
TEST_P(RenderScene, FramesReadBehindTheDrawingComeInOrderAndWhole) {
  std::vector<float> xs;
  for (int k = 0; k < 7; ++k) xs.push_back(-0.09f + 0.03f * static_cast<float>(k));
  std::vector<Image> alone;
  for (const float x : xs) alone.push_back(draw_box(Eigen::Vector3f(x, 0.0f, 0.0f), 0.2f));

  std::vector<Image> streamed;
  for (const float x : xs) {
    renderer_->begin_frame(camera_, DirectionalLight{});
    Eigen::Affine3f pose = Eigen::Affine3f::Identity();
    pose.translate(Eigen::Vector3f(x, 0.0f, 0.0f));
    pose.rotate(Eigen::AngleAxisf(0.2f, Eigen::Vector3f::UnitZ()));
    renderer_->draw(box_, pose);
    renderer_->submit_frame();
    while (context_->queued_frames() > context_->frames_behind())
      streamed.push_back(copy_image(context_->take_frame()));
  }
  // The back end holds the frames it said it would, no more.
  EXPECT_EQ(context_->queued_frames(), std::min<int>(context_->frames_behind(), 7));
  while (context_->queued_frames() > 0) streamed.push_back(copy_image(context_->take_frame()));

  ASSERT_EQ(streamed.size(), alone.size());
  for (std::size_t k = 0; k < alone.size(); ++k)
    EXPECT_EQ(rms_difference(streamed[k].view(), alone[k].view()), 0.0) << "frame " << k;
  // In drawing order: the box walks right.
  for (std::size_t k = 1; k < streamed.size(); ++k)
    EXPECT_GT(foreground_centroid(streamed[k].view()).x,
              foreground_centroid(streamed[k - 1].view()).x + 5.0)
        << "frame " << k;
}

TEST_P(RenderScene, AFrameIsNotReadAtOnceWhileOthersAreQueued) {
  draw_box(Eigen::Vector3f::Zero(), 0.0f);
  renderer_->begin_frame(camera_, DirectionalLight{});
  renderer_->submit_frame();
  EXPECT_THROW(context_->read_frame(), std::logic_error);
  renderer_->begin_frame(camera_, DirectionalLight{});
  EXPECT_THROW(renderer_->end_frame(), std::logic_error);
  context_->take_frame();
  EXPECT_THROW(context_->take_frame(), std::logic_error);
}

TEST_P(RenderScene, TheDemoSceneIsNotBlankAndCastsShadows) {
  const DemoScene scene = make_demo_scene();
  const auto render = [&](bool shadows, bool soft = false) {
    RendererOptions options;
    options.shadows = shadows;
    options.soft_shadows = soft;
    Renderer renderer(*context_, options);
    std::vector<MeshId> local;
    for (const MeshData& mesh : scene.meshes) local.push_back(renderer.upload(mesh));
    renderer.begin_frame(scene.camera, scene.light);
    for (const auto& instance : scene.instances)
      renderer.draw(local[instance.mesh], instance.pose, instance.casts_shadow);
    return copy_image(renderer.end_frame());
  };
  const Image lit = render(true);
  const Image flat = render(false);
  fl::test::keep_frame("demo_shadows", lit.view());
  fl::test::keep_frame("demo_no_shadows", flat.view());
  // Most of the frame is the scene, not the background.
  EXPECT_GT(count_pixels_unlike(lit.view(), kBackground, 12), lit.rgba.size() / 4 / 2);
  // Shadows darken a part of it and brighten nothing.
  std::size_t darker = 0;
  std::size_t brighter = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      int change = 0;
      for (std::size_t k = 0; k < 3; ++k) change += lit.at(x, y)[k] - flat.at(x, y)[k];
      darker += change < -6 ? 1 : 0;
      brighter += change > 2 ? 1 : 0;
    }
  }
  EXPECT_GT(darker, static_cast<std::size_t>(kWidth * kHeight / 100));
  EXPECT_EQ(brighter, 0u);
  // Soft shadows differ only along the shadows' edges.
  const Image soft = render(true, true);
  EXPECT_GT(rms_difference(soft.view(), lit.view()), 0.0);
  EXPECT_LT(rms_difference(soft.view(), lit.view()), 3.0);
}

TEST_P(RenderScene, TextDrawsInsideItsBoxAndNowhereElse) {
  renderer_->begin_frame(camera_, DirectionalLight{});
  const Rect box = renderer_->overlay().text("T = 0.794 ± 0.012 s  μₖ", Eigen::Vector2f(20, 30),
                                             16.0f, Color{0.0f, 0.0f, 0.0f});
  const Image frame = copy_image(renderer_->end_frame());
  fl::test::keep_frame("text", frame.view());
  EXPECT_GT(box.width, 100.0f);
  EXPECT_NEAR(box.height, 16.0f, 2.0f);
  std::size_t inside = 0;
  std::size_t outside = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool ink = frame.at(x, y)[0] < 200;
      const bool in_box = x >= box.x - 1 && x <= box.x + box.width + 1 && y >= box.y - 1 &&
                          y <= box.y + box.height + 1;
      (in_box ? inside : outside) += ink ? 1 : 0;
    }
  }
  EXPECT_GT(inside, static_cast<std::size_t>(box.width * box.height * 0.08f));
  EXPECT_EQ(outside, 0u);
}

TEST_P(RenderScene, ShapesFillTheirPixelsInTheirColours) {
  renderer_->begin_frame(camera_, DirectionalLight{});
  Overlay& overlay = renderer_->overlay();
  overlay.rect(Rect{10, 10, 40, 20}, Color{1.0f, 0.0f, 0.0f});
  overlay.rect(Rect{100, 10, 40, 20}, Color{0.0f, 0.0f, 0.0f, 0.5f});
  const std::vector<Eigen::Vector2f> trace = {{10, 100}, {60, 80}, {110, 120}, {160, 100}};
  overlay.polyline(trace, 2.0f, Color{0.0f, 0.3f, 1.0f});
  overlay.dot(Eigen::Vector2f(200, 100), 5.0f, Color{0.0f, 0.6f, 0.0f});
  const ImageView frame = renderer_->end_frame();
  fl::test::keep_frame("shapes", frame);
  EXPECT_EQ(frame.at(30, 20)[0], 255);
  EXPECT_EQ(frame.at(30, 20)[1], 0);
  EXPECT_EQ(frame.at(9, 20)[1], kBackground[1]);  // just outside
  // Half-transparent black over the background halves it.
  EXPECT_NEAR(frame.at(120, 20)[0], kBackground[0] / 2.0, 2.0);
  EXPECT_EQ(frame.at(120, 20)[3], 255);
  // On the polyline's first segment, and its marker.
  EXPECT_LT(frame.at(35, 90)[0], 60);
  EXPECT_GT(frame.at(200, 100)[1], 140);
  EXPECT_LT(frame.at(200, 100)[0], 30);
}

TEST_P(RenderScene, ABrokenShaderNamesItsStage) {
  try {
    ShaderProgram bad(context_->gl(), "bad", "#version 330 core\nvoid main() { oops; }\n",
                      "#version 330 core\nvoid main() {}\n");
    FAIL() << "a broken shader compiled";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("the vertex shader of 'bad' does not compile"),
              std::string::npos)
        << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(BackEnds, RenderScene, ::testing::ValuesIn(test::kGlBackends),
                         test::backend_test_name);

// The demo scene with a little overlay at 160x90.
Image demo_frame(GlContext& context) {
  Renderer renderer(context);
  DemoScene scene = make_demo_scene();
  scene.pose(0.012f, 0.4f);
  std::vector<MeshId> ids;
  for (const MeshData& mesh : scene.meshes) ids.push_back(renderer.upload(mesh));
  renderer.begin_frame(scene.camera, scene.light);
  for (const auto& instance : scene.instances)
    renderer.draw(ids[instance.mesh], instance.pose, instance.casts_shadow);
  renderer.overlay().rect(Rect{0, 0, 160, 14}, Color{0.0f, 0.0f, 0.0f, 0.55f});
  renderer.overlay().text("t = 1.23 s", Eigen::Vector2f(4, 1), 11.0f, Color{1.0f, 1.0f, 1.0f});
  const std::vector<Eigen::Vector2f> trace = {{100, 10}, {115, 4}, {130, 10}, {145, 4}};
  renderer.overlay().polyline(trace, 1.5f, Color{1.0f, 0.8f, 0.1f});
  return copy_image(renderer.end_frame());
}

// The demo scene against tests/render/golden/, on each back end. To refresh the golden image on
// purpose (after a deliberate change of the look), run this test with FRICTIONLAB_UPDATE_GOLDEN=1
// and look at the new PNG before committing it.
class RenderGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(RenderGolden, DemoSceneMatchesTheGoldenImage) {
  FL_REQUIRE_BACKEND(GetParam());
  const auto context = test::gl_context(GetParam(), 160, 90);
  const Image frame = demo_frame(*context);
  const std::string golden =
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/render/golden/demo_scene_160x90.png";
  const char* update = std::getenv("FRICTIONLAB_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_png(golden, frame.view());
    GTEST_SKIP() << "wrote the golden image " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden))
      << golden << " is missing; make it with FRICTIONLAB_UPDATE_GOLDEN=1";
  const Image expected = read_png(golden);
  const double rms = rms_difference(frame.view(), expected.view());
  // llvmpipe is deterministic for one Mesa version; the tolerance absorbs small changes of
  // rasterisation between versions and CPUs, not a changed scene.
  constexpr double kTolerance = 3.0;
  const std::string name = "golden_" + GetParam();
  if (rms > kTolerance) {
    fl::test::keep_frame(name + "_actual", frame.view());
    fl::test::keep_frame(name + "_difference",
                         difference_image(frame.view(), expected.view()).view());
  }
  EXPECT_LE(rms, kTolerance) << "RMS difference " << rms
                             << " (0-255) from the golden image; see render-test-output/" << name
                             << "_actual.png and _difference.png in the build folder";
}

INSTANTIATE_TEST_SUITE_P(BackEnds, RenderGolden, ::testing::ValuesIn(test::kGlBackends),
                         test::backend_test_name);

// Both back ends on one renderer (llvmpipe here: EGL has no GPU to find) draw the same pixels:
// measured RMS 0 on this machine, every pixel equal. On a GPU the EGL frame would differ, which
// this test then does not judge.
TEST(RenderBackEnds, OnOneRendererBothDrawTheSamePixels) {
  FL_REQUIRE_BACKEND("osmesa");
  FL_REQUIRE_BACKEND("egl");
  const auto osmesa = test::gl_context("osmesa", 160, 90);
  const auto egl = test::gl_context("egl", 160, 90);
  const auto renderer_of = [](const GlContext& c) {
    const std::string d = c.description();
    return d.substr(0, d.find(" (EGL"));
  };
  if (renderer_of(*osmesa) != renderer_of(*egl))
    GTEST_SKIP() << "different renderers: " << osmesa->description() << " / " << egl->description();
  osmesa->make_current();
  const Image a = demo_frame(*osmesa);
  egl->make_current();
  const Image b = demo_frame(*egl);
  EXPECT_EQ(rms_difference(a.view(), b.view()), 0.0);
}

}  // namespace
}  // namespace fl::render
