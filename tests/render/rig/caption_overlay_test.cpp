// Captions without GL: which caption a simulated time shows (its own `until`, else the next
// caption's start, the last until the run's end), how a long caption breaks into lines, and how
// one too long for three lines shrinks and is cut.
#include "render/rig/caption_overlay.hpp"

#include "render/components.hpp"
#include "render/overlay.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

namespace fl::render {
namespace {

std::string shown(const std::vector<Caption>& captions, double t) {
  return caption_at(captions, t).value_or("(none)");
}

TEST(CaptionAt, EachTimeShowsTheCaptionItFallsIn) {
  const std::vector<Caption> captions = {
      {1.0, std::nullopt, "first"},  // until the second's start
      {3.0, 4.0, "second"},          // its own end, then a gap
      {6.0, std::nullopt, "last"},   // until the run ends
  };
  EXPECT_EQ(shown(captions, 0.0), "(none)");
  EXPECT_EQ(shown(captions, 0.999), "(none)");
  EXPECT_EQ(shown(captions, 1.0), "first");
  EXPECT_EQ(shown(captions, 2.999), "first");
  EXPECT_EQ(shown(captions, 3.0), "second");
  EXPECT_EQ(shown(captions, 3.999), "second");
  EXPECT_EQ(shown(captions, 4.0), "(none)");
  EXPECT_EQ(shown(captions, 5.999), "(none)");
  EXPECT_EQ(shown(captions, 6.0), "last");
  EXPECT_EQ(shown(captions, 1e6), "last");
  EXPECT_EQ(shown({}, 1.0), "(none)");
}

// A frame's time is k times the rounded frame interval: at 30 fps frame 111 lands a hair below
// 3.7 s (3.6999999999999997) and shows the caption that starts at 3.7 s.
TEST(CaptionAt, AFrameAtACaptionsStartShowsIt) {
  const std::vector<Caption> captions = {{0.0, std::nullopt, "before"},
                                         {3.7, std::nullopt, "after"}};
  const double interval = 1.0 / 30.0;
  ASSERT_LT(111 * interval, 3.7);
  EXPECT_EQ(shown(captions, 111 * interval), "after");
  EXPECT_EQ(shown(captions, 110 * interval), "before");
}

// A measure of one unit a byte: lines of at most `width` bytes.
std::vector<std::string> wrap(std::string_view text, float width) {
  return wrap_text(text, width, [](std::string_view s) { return static_cast<float>(s.size()); });
}

TEST(WrapText, BreaksAtSpacesWithinTheWidth) {
  EXPECT_EQ(wrap("the plate slides back to the middle", 12),
            (std::vector<std::string>{"the plate", "slides back", "to the", "middle"}));
  EXPECT_EQ(wrap("short", 12), (std::vector<std::string>{"short"}));
  // Runs of spaces and the ends' spaces go; a line end in the text starts a line.
  EXPECT_EQ(wrap("  one   two\nthree  ", 40), (std::vector<std::string>{"one two", "three"}));
  EXPECT_EQ(wrap("a\n\nb", 40), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(wrap("   ", 40).empty());
}

TEST(WrapText, AWordWiderThanTheLineIsBrokenBetweenCharacters) {
  EXPECT_EQ(wrap("abcdefghij xy", 4), (std::vector<std::string>{"abcd", "efgh", "ij", "xy"}));
  EXPECT_EQ(wrap("ab cdefghij", 4), (std::vector<std::string>{"ab", "cdef", "ghij"}));
  // Never inside a character: "μ" is two bytes, so a line of 3 bytes holds one.
  EXPECT_EQ(wrap("\xce\xbc\xce\xbc\xce\xbc", 3),
            (std::vector<std::string>{"\xce\xbc", "\xce\xbc", "\xce\xbc"}));
}

// The layout with the overlay's own font (no GL: measuring text needs only the font). At
// 640x360 a caption is 15 px; one that needs more than three lines at 15 px is drawn a pixel
// smaller at a time, down to 12 px; one that needs more even then keeps three lines, the last cut
// with "…". Every line fits the 520 px width; at 1280x720 the sizes double.
TEST(LayoutCaption, LongTextShrinksToTwelvePixelsThenIsCutWithAnEllipsis) {
  if (!kHasRender) GTEST_SKIP() << "a build without rendering has no font";
  Overlay overlay;
  const std::string ellipsis = "\xe2\x80\xa6";
  const auto fits = [&](const CaptionLayout& l, float max_width) {
    for (const std::string& line : l.lines)
      if (overlay.measure_text(line, l.pixel_size).width > max_width) return false;
    return true;
  };
  const CaptionLayout one = layout_caption(overlay, 640, 360, "The rollers turn at 1600 rpm.");
  EXPECT_EQ(one.pixel_size, 15.0f);
  EXPECT_EQ(one.lines.size(), 1u);

  // Words enough for four lines at 15 px and three at some smaller size.
  std::string medium;
  for (int words = 0; words < 40; ++words) {  // bounded: a layout that never shrinks fails below
    medium += "the plate slides back to the middle ";
    if (layout_caption(overlay, 640, 360, medium).pixel_size < 15.0f) break;
  }
  const CaptionLayout shrunk = layout_caption(overlay, 640, 360, medium);
  EXPECT_LT(shrunk.pixel_size, 15.0f);
  EXPECT_GE(shrunk.pixel_size, 12.0f);
  EXPECT_EQ(shrunk.lines.size(), 3u);
  EXPECT_FALSE(shrunk.lines.back().ends_with(ellipsis));
  EXPECT_TRUE(fits(shrunk, 520.0f));

  std::string long_text;
  for (int i = 0; i < 40; ++i) long_text += "the plate slides back to the middle ";
  for (const auto& [width, height, scale] : {std::tuple{640, 360, 1.0f}, {1280, 720, 2.0f}}) {
    const CaptionLayout cut = layout_caption(overlay, width, height, long_text);
    EXPECT_EQ(cut.pixel_size, 12.0f * scale) << width;
    ASSERT_EQ(cut.lines.size(), 3u) << width;
    EXPECT_TRUE(cut.lines.back().ends_with(ellipsis)) << cut.lines.back();
    EXPECT_TRUE(fits(cut, 520.0f * scale)) << width;
  }
}

// The title card's title (run --title, at most 200 characters): one line at 28 px when it fits,
// else wrapped to three lines at most and shrunk until they fit a 640-pixel frame's 608 px.
TEST(FitText, ATitleWrapsToThreeLinesThenShrinks) {
  if (!kHasRender) GTEST_SKIP() << "a build without rendering has no font";
  Overlay overlay;
  const FittedText short_title = fit_text(overlay, "Friction, live", 608.0f, 28.0f, 10.0f, 1.0f, 3);
  EXPECT_EQ(short_title.pixel_size, 28.0f);
  EXPECT_EQ(short_title.lines, std::vector<std::string>{"Friction, live"});
  std::string longest;
  while (longest.size() + 10 <= 200) longest += "friction ";
  const FittedText fitted = fit_text(overlay, longest, 608.0f, 28.0f, 10.0f, 1.0f, 3);
  EXPECT_LE(fitted.lines.size(), 3u);
  EXPECT_GE(fitted.lines.size(), 2u);
  EXPECT_LT(fitted.pixel_size, 28.0f);
  EXPECT_GE(fitted.pixel_size, 10.0f);
  std::string joined;
  for (const std::string& line : fitted.lines) {
    EXPECT_LE(overlay.measure_text(line, fitted.pixel_size).width, 608.0f) << line;
    joined += (joined.empty() ? "" : " ") + line;
  }
  EXPECT_EQ(joined + " ", longest);  // every word kept: no ellipsis at 200 characters
}

}  // namespace
}  // namespace fl::render
