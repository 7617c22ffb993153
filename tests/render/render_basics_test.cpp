// The parts of the render layer that need no GL: images, camera matrices, meshes, UTF-8, the
// back-end choice, the threaded sink. They build and run in every configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/components.hpp"
#include "render/demo_scene.hpp"
#include "render/font.hpp"
#include "render/gl/gl_context.hpp"
#include "render/mesh_data.hpp"
#include "render/sinks/frame_sink.hpp"
#include "render/sinks/png.hpp"
#include "render/sinks/video.hpp"

namespace fl::render {
namespace {

TEST(RenderImage, RmsOfIdenticalImagesIsZeroAndOfAShiftedChannelIsTheShift) {
  Image a(4, 3);
  Image b(4, 3);
  for (auto& v : a.rgba) v = 100;
  for (auto& v : b.rgba) v = 100;
  EXPECT_EQ(rms_difference(a.view(), b.view()), 0.0);
  for (std::size_t i = 0; i < b.rgba.size(); i += 4) b.rgba[i] = 110;  // red +10 everywhere
  EXPECT_NEAR(rms_difference(a.view(), b.view()), std::sqrt(100.0 / 3.0), 1e-12);
  EXPECT_THROW(rms_difference(a.view(), Image(3, 4).view()), std::invalid_argument);
}

TEST(RenderImage, ABottomUpViewReadsTopDown) {
  Image stored(2, 3);
  for (int y = 0; y < 3; ++y) stored.row(y)[0] = static_cast<std::uint8_t>(y);
  // The same memory seen bottom-up: row 0 of the view is the last stored row.
  const ImageView flipped{stored.row(2), 2, 3, -8};
  EXPECT_EQ(flipped.at(0, 0)[0], 2);
  EXPECT_EQ(copy_image(flipped).at(0, 2)[0], 0);
}

TEST(RenderCamera, LookAtPutsTheTargetOnTheAxisInFrontOfTheCamera) {
  const Eigen::Matrix4f view =
      look_at(Eigen::Vector3f(1, 2, 3), Eigen::Vector3f(4, 6, 3), Eigen::Vector3f::UnitZ());
  const Eigen::Vector4f target = view * Eigen::Vector4f(4, 6, 3, 1);
  EXPECT_NEAR(target.x(), 0.0f, 1e-5f);
  EXPECT_NEAR(target.y(), 0.0f, 1e-5f);
  EXPECT_NEAR(target.z(), -5.0f, 1e-5f);  // 5 m in front, down -z
  // World up stays up on the screen.
  const Eigen::Vector4f above = view * Eigen::Vector4f(4, 6, 4, 1);
  EXPECT_GT(above.y(), 0.0f);
}

TEST(RenderCamera, PerspectiveMapsTheFrustumEdgesToTheClipCube) {
  const float fov = 1.0f;
  const Eigen::Matrix4f p = perspective(fov, 2.0f, 0.1f, 10.0f);
  const auto ndc = [&](const Eigen::Vector3f& v) {
    const Eigen::Vector4f c = p * v.homogeneous();
    return Eigen::Vector3f(c.head<3>() / c.w());
  };
  const float top = std::tan(fov / 2.0f);
  EXPECT_NEAR(ndc(Eigen::Vector3f(0, 0, -0.1f)).z(), -1.0f, 1e-5f);
  EXPECT_NEAR(ndc(Eigen::Vector3f(0, 0, -10.0f)).z(), 1.0f, 1e-4f);
  EXPECT_NEAR(ndc(Eigen::Vector3f(0, top, -1.0f)).y(), 1.0f, 1e-5f);
  EXPECT_NEAR(ndc(Eigen::Vector3f(2.0f * top, 0, -1.0f)).x(), 1.0f, 1e-5f);
}

TEST(RenderCamera, ProjectToPixelCentresTheTargetAndDropsPointsBehind) {
  Camera camera;
  camera.position = Eigen::Vector3f(0, -1, 0);
  camera.target = Eigen::Vector3f::Zero();
  const auto centre = project_to_pixel(camera, 640, 360, camera.target);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->x(), 320.0f, 1e-3f);
  EXPECT_NEAR(centre->y(), 180.0f, 1e-3f);
  const auto up = project_to_pixel(camera, 640, 360, Eigen::Vector3f(0, 0, 0.1f));
  ASSERT_TRUE(up.has_value());
  EXPECT_LT(up->y(), 180.0f);  // rows count down from the top
  EXPECT_FALSE(project_to_pixel(camera, 640, 360, Eigen::Vector3f(0, -2, 0)).has_value());
}

TEST(RenderMesh, BoxHasTwelveOutwardTriangles) {
  const MeshData box = make_box(Eigen::Vector3f(1, 2, 3), Color{});
  box.validate();
  ASSERT_EQ(box.triangle_count(), 12u);
  for (std::size_t t = 0; t < box.triangle_count(); ++t) {
    const auto& a = box.positions[box.indices[3 * t]];
    const auto& b = box.positions[box.indices[3 * t + 1]];
    const auto& c = box.positions[box.indices[3 * t + 2]];
    const Eigen::Vector3f face_normal = (b - a).cross(c - a);
    // Counter-clockwise seen from outside: the winding's normal points away from the centre.
    EXPECT_GT(face_normal.dot((a + b + c) / 3.0f), 0.0f) << "triangle " << t;
  }
}

TEST(RenderMesh, CylinderTrianglesFaceOutward) {
  const MeshData cylinder = make_cylinder(0.5f, 2.0f, 12, Color{});
  cylinder.validate();
  EXPECT_EQ(cylinder.triangle_count(), 12u * 2 + 12u * 2);
  for (std::size_t t = 0; t < cylinder.triangle_count(); ++t) {
    const auto& a = cylinder.positions[cylinder.indices[3 * t]];
    const auto& b = cylinder.positions[cylinder.indices[3 * t + 1]];
    const auto& c = cylinder.positions[cylinder.indices[3 * t + 2]];
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0f), 0.0f) << "triangle " << t;
  }
}

TEST(RenderMesh, ValidateRejectsAnIndexPastTheEnd) {
  MeshData mesh = make_box(Eigen::Vector3f::Ones(), Color{});
  mesh.indices.back() = 99;
  EXPECT_THROW(mesh.validate(), std::invalid_argument);
}

TEST(RenderMesh, DemoSceneIsAboutSixThousandTriangles) {
  const DemoScene scene = make_demo_scene();
  EXPECT_GT(scene.triangle_count(), 5000u);
  EXPECT_LT(scene.triangle_count(), 7000u);
}

TEST(RenderText, Utf8DecodesSignsAndReplacesBrokenBytes) {
  EXPECT_EQ(decode_utf8("T ± dT"), (std::vector<char32_t>{U'T', U' ', U'±', U' ', U'd', U'T'}));
  EXPECT_EQ(decode_utf8("μₖ"), (std::vector<char32_t>{U'μ', U'ₖ'}));
  EXPECT_EQ(decode_utf8("a\xff"), (std::vector<char32_t>{U'a', 0xFFFD}));
  EXPECT_EQ(decode_utf8("\xe2\x82"), (std::vector<char32_t>{0xFFFD, 0xFFFD}));
}

// Sets an environment variable for one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_.empty()) {
      ::unsetenv(name_);
    } else {
      ::setenv(name_, old_.c_str(), 1);
    }
  }

 private:
  const char* name_;
  std::string old_;
};

TEST(RenderBackend, CommandLineBeatsEnvironmentBeatsDefault) {
  {
    ScopedEnv env(kGlBackendVariable, nullptr);
    EXPECT_EQ(gl_backend_request().name, "auto");
    EXPECT_EQ(gl_backend_request().source, "default");
  }
  {
    ScopedEnv env(kGlBackendVariable, "egl");
    EXPECT_EQ(gl_backend_request().name, "egl");
    EXPECT_EQ(gl_backend_request().source, "FRICTIONLAB_GL");
    EXPECT_EQ(gl_backend_request("osmesa").name, "osmesa");
    EXPECT_EQ(gl_backend_request("osmesa").source, "--gl");
  }
}

TEST(RenderBackend, AnUnknownNameListsTheValidOnes) {
  ScopedEnv env(kGlBackendVariable, "glfw");
  try {
    make_gl_context(GlContextOptions{});
    FAIL() << "an unknown back end was accepted";
  } catch (const RenderError& e) {
    EXPECT_STREQ(e.what(),
                 "unknown GL back end 'glfw' (from FRICTIONLAB_GL); valid back ends: osmesa, "
                 "egl, auto");
  }
}

TEST(RenderBackend, WithoutEglTheEglBackEndSaysSo) {
  if (kHasEgl) GTEST_SKIP() << "this build has EGL";
  GlContextOptions options;
  options.backend = "egl";
  try {
    make_gl_context(options);
    FAIL() << "the egl back end started";
  } catch (const MissingComponent& e) {
    EXPECT_NE(std::string(e.what()).find("'egl'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-DFRICTIONLAB_WITH_EGL=ON"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("libegl-dev"), std::string::npos) << e.what();
  }
}

TEST(RenderBackend, WithoutRenderEveryBackEndFailsNamingOsmesa) {
  if (kHasRender) GTEST_SKIP() << "this build has OSMesa";
  for (const char* name : {"osmesa", "auto"}) {
    GlContextOptions options;
    options.backend = name;
    try {
      make_gl_context(options);
      FAIL() << name << " started without OSMesa";
    } catch (const MissingComponent& e) {
      EXPECT_NE(std::string(e.what()).find("OSMesa"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("FRICTIONLAB_WITH_RENDER=ON"), std::string::npos);
    }
  }
}

TEST(RenderBackend, WithoutOsmesaEveryBackEndFailsListingTheBuildsBackEnds) {
  if (kHasOsmesa || kHasEgl) GTEST_SKIP() << "this build has a GL back end";
  EXPECT_EQ(compiled_gl_backends(), "none");
  for (const char* name : {"osmesa", "auto"}) {
    GlContextOptions options;
    options.backend = name;
    try {
      make_gl_context(options);
      FAIL() << name << " started without a GL back end";
    } catch (const MissingComponent& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("OSMesa"), std::string::npos) << message;
      EXPECT_NE(message.find("GL back ends in this build: none"), std::string::npos) << message;
      EXPECT_NE(message.find("-DFRICTIONLAB_WITH_OSMESA=ON"), std::string::npos) << message;
    }
  }
}

TEST(RenderBackend, WithoutVideoAnMp4FailsNamingLibav) {
  if (kHasVideo) GTEST_SKIP() << "this build has libav";
  try {
    make_mp4_sink(VideoOptions{"x.mp4"});
    FAIL() << "an MP4 sink opened without libav";
  } catch (const MissingComponent& e) {
    EXPECT_NE(std::string(e.what()).find("libavcodec"), std::string::npos) << e.what();
  }
}

// A sink that records what it got, and can be told to fail.
class RecordingSink : public FrameSink {
 public:
  std::vector<int> first_bytes;
  bool finished = false;
  int fail_at = -1;

  void write(const ImageView& frame) override {
    if (static_cast<int>(first_bytes.size()) == fail_at) throw RenderError("disk full");
    first_bytes.push_back(frame.pixels[0]);
  }
  void finish() override { finished = true; }
  std::size_t frame_count() const override { return first_bytes.size(); }
};

TEST(RenderThreadedSink, PassesEveryFrameInOrderThenFinishes) {
  auto inner = std::make_unique<RecordingSink>();
  RecordingSink* seen = inner.get();
  ThreadedSink sink(std::move(inner), 2);
  Image frame(8, 4);
  for (int i = 0; i < 50; ++i) {
    frame.rgba[0] = static_cast<std::uint8_t>(i);
    sink.write(frame.view());  // the frame may be changed as soon as write returns
  }
  sink.finish();
  ASSERT_EQ(seen->first_bytes.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(seen->first_bytes[static_cast<std::size_t>(i)], i);
  EXPECT_TRUE(seen->finished);
  EXPECT_EQ(sink.frame_count(), 50u);
}

TEST(RenderThreadedSink, RethrowsTheInnerSinksError) {
  auto inner = std::make_unique<RecordingSink>();
  inner->fail_at = 3;
  ThreadedSink sink(std::move(inner), 2);
  const Image frame(8, 4);
  EXPECT_THROW(
      {
        for (int i = 0; i < 100; ++i) sink.write(frame.view());
        sink.finish();
      },
      RenderError);
}

// The pool writes every frame to its own file, each the frame given (whichever thread encoded
// it), the same bytes the one-thread sink writes; an earlier run's frames are refused as there.
TEST(RenderPngPoolSink, WritesEveryFrameToItsFileAsTheOneThreadSinkDoes) {
  if (!kHasRender) GTEST_SKIP() << "this build has no PNG writer";
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "fl-png-pool-test";
  fs::remove_all(root);
  PngSinkOptions pooled, single;
  pooled.directory = (root / "pool").string();
  single.directory = (root / "one").string();
  auto pool = make_png_pool_sink(pooled, 3);
  auto one = make_png_sink(single);
  Image frame(16, 8);
  for (int i = 0; i < 40; ++i) {
    for (std::size_t k = 0; k < frame.rgba.size(); ++k)
      frame.rgba[k] = static_cast<std::uint8_t>((k * 7 + static_cast<std::size_t>(i) * 13) % 251);
    pool->write(frame.view());  // the frame may be changed as soon as write returns
    one->write(frame.view());
  }
  pool->finish();
  one->finish();
  EXPECT_EQ(pool->frame_count(), 40u);
  for (int i = 0; i < 40; ++i) {
    const std::string name = png_frame_name(pooled, i);
    const auto bytes = [](const fs::path& path) {
      std::ifstream in(path, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    };
    const std::string pa = bytes(root / "pool" / name), pb = bytes(root / "one" / name);
    ASSERT_FALSE(pa.empty()) << name;
    EXPECT_EQ(pa, pb) << name;
    const Image back = read_png((root / "pool" / name).string());
    EXPECT_EQ(back.rgba[5], static_cast<std::uint8_t>((5 * 7 + i * 13) % 251)) << name;
  }
  EXPECT_THROW(make_png_pool_sink(pooled, 2), RenderError);
  fs::remove_all(root);
}

TEST(RenderPngPoolSink, RethrowsAnEncodersError) {
  if (!kHasRender) GTEST_SKIP() << "this build has no PNG writer";
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "fl-png-pool-error-test";
  fs::remove_all(root);
  PngSinkOptions options;
  options.directory = root.string();
  auto pool = make_png_pool_sink(options, 2);
  fs::remove_all(root);  // a file where the folder was: the encoders cannot write
  std::ofstream(root) << "not a folder";
  const Image frame(8, 4);
  EXPECT_ANY_THROW({
    for (int i = 0; i < 20; ++i) pool->write(frame.view());
    pool->finish();
  });
  fs::remove_all(root);
}

TEST(RenderPngNames, AreZeroPadded) {
  PngSinkOptions options;
  EXPECT_EQ(png_frame_name(options, 42), "frame_000042.png");
  options.prefix = "rig-";
  options.digits = 3;
  EXPECT_EQ(png_frame_name(options, 1234), "rig-1234.png");
}

}  // namespace
}  // namespace fl::render
