// Helpers of the render tests: skipping when a component is not built (FL_REQUIRE_RENDER for
// the drawing layer alone, FL_REQUIRE_GL to draw frames, FL_REQUIRE_VIDEO), and keeping frames
// under the build folder for a person to look at.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "render/components.hpp"
#include "render/image.hpp"
#include "render/png.hpp"

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

#define FL_REQUIRE_VIDEO()                                                              \
  do {                                                                                  \
    if (!fl::render::kHasVideo) GTEST_SKIP() << "built without FRICTIONLAB_WITH_VIDEO"; \
  } while (0)

namespace fl::test {

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
