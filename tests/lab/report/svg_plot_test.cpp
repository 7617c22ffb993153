// The report's plots: round ticks, and a long series drawn through each pixel column's extremes,
// so its largest and smallest values are in the picture however many points it has.
#include "lab/report/svg_plot.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "text/html_text.hpp"

namespace fl {
namespace {

TEST(SvgPlot, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
  const std::vector<double> t = round_ticks(0.0, 10.0, 8);
  ASSERT_EQ(t.size(), 6u);  // 10 / 8 = 1.25: steps of 2
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], 2.0 * static_cast<double>(i), 1e-12);
  const std::vector<double> small = round_ticks(-0.031, 0.032, 5);
  EXPECT_NEAR(small[1] - small[0], 0.02, 1e-15);  // 0.0126: steps of 0.02
  EXPECT_NEAR(small.front(), -0.02, 1e-15);
  EXPECT_NEAR(small.back(), 0.02, 1e-15);
}

// The y pixel of each point of the polyline ("x,y x,y ...").
std::vector<double> ys_of(const std::string& svg) {
  const std::string key = "points=\"";
  const std::size_t start = svg.find(key) + key.size();
  std::istringstream points(svg.substr(start, svg.find('"', start) - start));
  std::vector<double> ys;
  for (std::string pair; points >> pair;) ys.push_back(std::stod(pair.substr(pair.find(',') + 1)));
  return ys;
}

TEST(SvgPlot, AMillionPointsAreDrawnThroughTheirExtremes) {
  // A sine of 20 periods, its peaks between samples but one: the sample at t = 0.5 / 40 of each
  // period's first quarter... every 1e-6: the largest sample is 1 - O(1e-9), the least -1 + ...
  SvgSeries s;
  s.color = "#000";
  const int n = 1'000'000;
  for (int i = 0; i < n; ++i) {
    const double t = i * 1e-6;
    s.x.push_back(t);
    s.y.push_back(std::sin(2.0 * std::numbers::pi * 20.0 * t));
  }
  // One spike, one sample wide: a glitch in the signal must not vanish from the picture.
  s.y[654321] = 3.0;
  SvgPlot plot{"test", "t (s)", "y", {s}, 680, 240};
  const std::string svg = svg_line_plot(plot);
  const std::vector<double> ys = ys_of(svg);
  EXPECT_LT(ys.size(), 4 * 680u) << "the picture holds more points than its columns need";
  // y spans -1 to 3, padded by 5 % each side, onto pixels 12 to 200 (240 - 40).
  const double top = 12.0, height = 188.0, least = -1.0 - 0.2, most = 3.0 + 0.2;
  const auto pixel = [&](double y) { return top + (most - y) / (most - least) * height; };
  const double highest = *std::min_element(ys.begin(), ys.end());
  const double lowest = *std::max_element(ys.begin(), ys.end());
  EXPECT_NEAR(highest, pixel(3.0), 0.01);
  EXPECT_NEAR(lowest, pixel(-1.0), 0.01);
}

TEST(SvgPlot, TextIsEscaped) {
  EXPECT_EQ(html_text("<b>\"Smith, J.\" & 'co'</b>"),
            "&lt;b&gt;&quot;Smith, J.&quot; &amp; 'co'&lt;/b&gt;");
  SvgPlot plot{"a <script>", "t", "y", {}, 100, 100};
  EXPECT_EQ(svg_line_plot(plot).find("<script>"), std::string::npos);
}

}  // namespace
}  // namespace fl
