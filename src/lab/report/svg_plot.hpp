// A line plot as SVG text, for a report that prints as vector graphics: axes with round ticks,
// labels, one or more series. A long series is drawn through its least and most value in each of
// the plot's pixel columns, which keeps its every extreme at any printed size.
#pragma once

#include <string>
#include <vector>

namespace fl {

struct SvgSeries {
  std::vector<double> x;
  std::vector<double> y;
  std::string label;    // in the legend ("" : none)
  std::string color;    // a CSS colour
  bool points = false;  // a dot at each value, no line between them
};

struct SvgPlot {
  std::string title;    // the plot's accessible name
  std::string x_label;  // with its unit: "t (s)"
  std::string y_label;
  std::vector<SvgSeries> series;
  int width = 680;  // the viewBox, in CSS px
  int height = 240;
  std::string decimal_sign = ".";  // the ticks' ("," in French)
};

// The plot as an <svg> element (role="img", titled); a plot with no finite point says so.
std::string svg_line_plot(const SvgPlot& plot);

// Round tick values covering [least, most]: 1, 2 or 5 times a power of ten apart, about `count`.
std::vector<double> round_ticks(double least, double most, int count);

}  // namespace fl
