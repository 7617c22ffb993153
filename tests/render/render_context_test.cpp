// The OSMesa back end: a context starts, a cleared colour reads back exactly, the frame's rows
// are top-down, and the multisampled frame resolves.
#include <gtest/gtest.h>

#include <string>

#include "render/gl_api.hpp"
#include "render/gl_context.hpp"
#include "render_test_support.hpp"

namespace fl::render {
namespace {

std::unique_ptr<GlContext> osmesa(int width, int height, int samples) {
  GlContextOptions options;
  options.width = width;
  options.height = height;
  options.samples = samples;
  options.backend = "osmesa";
  return make_gl_context(options);
}

class RenderContext : public ::testing::TestWithParam<int> {};

TEST_P(RenderContext, AClearedColourReadsBackExactly) {
  FL_REQUIRE_GL();
  const auto context = osmesa(64, 48, GetParam());
  EXPECT_EQ(context->backend_name(), "osmesa");
  EXPECT_EQ(context->width(), 64);
  EXPECT_EQ(context->height(), 48);
  EXPECT_EQ(context->samples(), GetParam());
  const GlApi& gl = context->gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, context->frame_framebuffer());
  gl.Viewport(0, 0, 64, 48);
  // 51/255, 102/255, 204/255 are exact in 8 bits.
  gl.ClearColor(0.2f, 0.4f, 0.8f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  const ImageView frame = context->read_frame();
  ASSERT_EQ(frame.width, 64);
  ASSERT_EQ(frame.height, 48);
  EXPECT_EQ(count_pixels_unlike(frame, {51, 102, 204}), 0u);
  EXPECT_EQ(frame.at(0, 0)[3], 255);
}

TEST_P(RenderContext, RowsAreTopDown) {
  FL_REQUIRE_GL();
  const auto context = osmesa(32, 32, GetParam());
  const GlApi& gl = context->gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, context->frame_framebuffer());
  gl.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  // GL's y runs up: clearing GL rows 24..31 paints the top 8 rows of the frame.
  gl.Enable(GL_SCISSOR_TEST);
  gl.Scissor(0, 24, 32, 8);
  gl.ClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Disable(GL_SCISSOR_TEST);
  const ImageView frame = context->read_frame();
  EXPECT_EQ(frame.at(5, 0)[0], 255);
  EXPECT_EQ(frame.at(5, 7)[0], 255);
  EXPECT_EQ(frame.at(5, 8)[0], 0);
  EXPECT_EQ(frame.at(5, 31)[0], 0);
}

INSTANTIATE_TEST_SUITE_P(Samples, RenderContext, ::testing::Values(1, 4),
                         [](const auto& param_info) {
                           return "x" + std::to_string(param_info.param);
                         });

TEST(RenderContextInfo, IsOpenGl45CoreOnLlvmpipe) {
  FL_REQUIRE_GL();
  const auto context = osmesa(16, 16, 4);
  const std::string text = context->description();
  EXPECT_NE(text.find("Core Profile"), std::string::npos) << text;
  EXPECT_NE(text.find("llvmpipe"), std::string::npos) << text;
}

TEST(RenderContextInfo, RefusesSizesAndSampleCountsItCannotDo) {
  FL_REQUIRE_GL();
  EXPECT_THROW(osmesa(0, 10, 4), RenderError);
  EXPECT_THROW(osmesa(10, 10, 8), RenderError);
}

}  // namespace
}  // namespace fl::render
