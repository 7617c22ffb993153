// Each GL back end (OSMesa, EGL): a context starts, a cleared colour reads back exactly, the
// frame's rows are top-down, and the multisampled frame resolves.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "render/gl/gl_api.hpp"
#include "render/gl/gl_context.hpp"
#include "render_test_support.hpp"

namespace fl::render {
namespace {

// Each back end with 1 and 4 samples.
class RenderContext : public ::testing::TestWithParam<std::tuple<std::string, int>> {
 protected:
  const std::string& backend() const { return std::get<0>(GetParam()); }
  int samples() const { return std::get<1>(GetParam()); }
  std::unique_ptr<GlContext> make(int width, int height) const {
    return test::gl_context(backend(), width, height, samples());
  }
};

TEST_P(RenderContext, AClearedColourReadsBackExactly) {
  FL_REQUIRE_BACKEND(backend());
  const auto context = make(64, 48);
  EXPECT_EQ(context->backend_name(), backend());
  EXPECT_EQ(context->width(), 64);
  EXPECT_EQ(context->height(), 48);
  EXPECT_EQ(context->samples(), samples());
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
  FL_REQUIRE_BACKEND(backend());
  const auto context = make(32, 32);
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

// A context made, dropped and made again: EGL's display is shared by the process's contexts and
// ended with the last one, so a second context must find it working.
TEST_P(RenderContext, ASecondContextStartsAfterTheFirstAndBesideIt) {
  FL_REQUIRE_BACKEND(backend());
  { const auto first = make(16, 16); }
  const auto a = make(16, 16);
  const auto b = make(24, 16);
  a->make_current();
  EXPECT_EQ(a->read_frame().width, 16);
  b->make_current();
  EXPECT_EQ(b->read_frame().width, 24);
}

INSTANTIATE_TEST_SUITE_P(BackEnds, RenderContext,
                         ::testing::Combine(::testing::ValuesIn(test::kGlBackends),
                                            ::testing::Values(1, 4)),
                         [](const auto& param_info) {
                           return std::get<0>(param_info.param) + "_x" +
                                  std::to_string(std::get<1>(param_info.param));
                         });

class RenderContextInfo : public ::testing::TestWithParam<std::string> {};

// This machine has no GPU: both back ends give Mesa's llvmpipe.
TEST_P(RenderContextInfo, IsOpenGl45CoreOnLlvmpipe) {
  FL_REQUIRE_BACKEND(GetParam());
  const auto context = test::gl_context(GetParam(), 16, 16, 4);
  const std::string text = context->description();
  EXPECT_NE(text.find("Core Profile"), std::string::npos) << text;
  EXPECT_NE(text.find("llvmpipe"), std::string::npos) << text;
}

TEST_P(RenderContextInfo, RefusesSizesAndSampleCountsItCannotDo) {
  FL_REQUIRE_BACKEND(GetParam());
  EXPECT_THROW(test::gl_context(GetParam(), 0, 10, 4), RenderError);
  EXPECT_THROW(test::gl_context(GetParam(), 10, 10, 8), RenderError);
}

INSTANTIATE_TEST_SUITE_P(BackEnds, RenderContextInfo, ::testing::ValuesIn(test::kGlBackends),
                         test::backend_test_name);

}  // namespace
}  // namespace fl::render
