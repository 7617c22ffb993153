// Helpers of the render tests: skipping when a component is not built (FL_REQUIRE_RENDER for
// the drawing layer alone, FL_REQUIRE_GL to draw frames, FL_REQUIRE_VIDEO), and keeping frames
// under the build folder for a person to look at.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "render/components.hpp"
#include "render/gl/gl_context.hpp"
#include "render/image.hpp"
#include "render/sinks/png.hpp"

#define FL_REQUIRE_RENDER()                                                               \
  do {                                                                                    \
    if (!fl::render::kHasRender) GTEST_SKIP() << "built without FRICTIONLAB_WITH_RENDER"; \
  } while (0)

// Drawing frames needs the drawing layer and a GL back end (today OSMesa).
#define FL_REQUIRE_GL()                                                                   \
  do {                                                                                    \
    FL_REQUIRE_RENDER();                                                                  \
    if (!fl::render::kHasOsmesa) GTEST_SKIP() << "built without FRICTIONLAB_WITH_OSMESA"; \
  } while (0)

// Drawing frames on one back end ("osmesa" or "egl"): skips when it is not built.
#define FL_REQUIRE_BACKEND(name)                                  \
  do {                                                            \
    FL_REQUIRE_RENDER();                                          \
    if (std::string(name) == "osmesa" && !fl::render::kHasOsmesa) \
      GTEST_SKIP() << "built without FRICTIONLAB_WITH_OSMESA";    \
    if (std::string(name) == "egl" && !fl::render::kHasEgl)       \
      GTEST_SKIP() << "built without FRICTIONLAB_WITH_EGL";       \
  } while (0)

#define FL_REQUIRE_VIDEO()                                                              \
  do {                                                                                  \
    if (!fl::render::kHasVideo) GTEST_SKIP() << "built without FRICTIONLAB_WITH_VIDEO"; \
  } while (0)

namespace fl::test {

// The GL back ends the drawing tests run on, each a test parameter.
inline const std::string kGlBackends[] = {"osmesa", "egl"};

// A context of the back end, w x h, with `samples`.
inline std::unique_ptr<fl::render::GlContext> gl_context(const std::string& backend, int width,
                                                         int height, int samples = 4) {
  fl::render::GlContextOptions options;
  options.width = width;
  options.height = height;
  options.samples = samples;
  options.backend = backend;
  return fl::render::make_gl_context(options);
}

// Test names: "osmesa", "egl".
inline std::string backend_test_name(const ::testing::TestParamInfo<std::string>& info) {
  return info.param;
}

// A fresh folder for one test's files under the build tree.
inline std::filesystem::path render_output_dir(const std::string& name) {
  const auto dir = std::filesystem::path(FRICTIONLAB_TEST_BINARY_DIR) / "render-test-output" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes a frame as build/.../render-test-output/<name>.png to look at.
inline void keep_frame(const std::string& name, const fl::render::ImageView& frame) {
  const auto dir = std::filesystem::path(FRICTIONLAB_TEST_BINARY_DIR) / "render-test-output";
  std::filesystem::create_directories(dir);
  fl::render::write_png((dir / (name + ".png")).string(), frame);
}

}  // namespace fl::test
