#include "lab/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "text/html_text.hpp"

namespace fl {
namespace {

struct Span {
  double least = std::numeric_limits<double>::infinity();
  double most = -std::numeric_limits<double>::infinity();
  void take(double v) {
    if (!std::isfinite(v)) return;
    least = std::min(least, v);
    most = std::max(most, v);
  }
  bool empty() const { return !(least <= most); }
};

// The series' points, at most two per pixel column (its least and most there, in time order).
std::vector<std::pair<double, double>> column_extremes(const SvgSeries& s, double x0, double x1,
                                                       int columns) {
  std::vector<std::pair<double, double>> out;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (n <= static_cast<std::size_t>(2 * columns)) {
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) out.emplace_back(s.x[i], s.y[i]);
    return out;
  }
  int column = -1;
  std::size_t lo = 0, hi = 0;
  bool open = false;
  const auto flush = [&] {
    if (!open) return;
    const std::size_t a = std::min(lo, hi), b = std::max(lo, hi);
    out.emplace_back(s.x[a], s.y[a]);
    if (b != a) out.emplace_back(s.x[b], s.y[b]);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
    const int c = static_cast<int>(std::floor((s.x[i] - x0) / (x1 - x0) * columns));
    if (c != column || !open) {
      flush();
      column = c;
      lo = hi = i;
      open = true;
    } else {
      if (s.y[i] < s.y[lo]) lo = i;
      if (s.y[i] > s.y[hi]) hi = i;
    }
  }
  flush();
  return out;
}

std::string tick_text(double v, double step, const std::string& sign) {
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  const double shown = std::fabs(v) < 0.5 * step ? 0.0 : v;
  std::string text = fmt::format("{:.{}f}", shown, decimals);
  if (sign != ".") std::replace(text.begin(), text.end(), '.', sign.empty() ? '.' : sign[0]);
  return text;
}

}  // namespace

std::vector<double> round_ticks(double least, double most, int count) {
  if (!(most > least) || count < 1) return {least};
  const double raw = (most - least) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  std::vector<double> ticks;
  for (double v = std::ceil(least / step - 1e-9) * step; v <= most + 1e-9 * step; v += step)
    ticks.push_back(v);
  return ticks;
}

std::string svg_line_plot(const SvgPlot& plot) {
  const double left = 64, right = 12, top = 12, bottom = 40;
  const double w = plot.width - left - right, h = plot.height - top - bottom;
  Span xs, ys;
  for (const SvgSeries& s : plot.series) {
    for (double v : s.x) xs.take(v);
    for (double v : s.y) ys.take(v);
  }
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {} {}\" role=\"img\" "
      "class=\"plot\"><title>{}</title>\n",
      plot.width, plot.height, html_text(plot.title));
  if (xs.empty() || ys.empty()) {
    out += fmt::format("<text x=\"{}\" y=\"{}\">no data</text></svg>\n", left, top + h / 2);
    return out;
  }
  if (xs.most == xs.least) xs.most = xs.least + 1.0;
  const double pad = ys.most > ys.least ? 0.05 * (ys.most - ys.least) : 1.0;
  ys.least -= pad;
  ys.most += pad;
  const auto px = [&](double x) { return left + (x - xs.least) / (xs.most - xs.least) * w; };
  const auto py = [&](double y) { return top + (ys.most - y) / (ys.most - ys.least) * h; };
  // Axes and ticks.
  out += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#555\" "
      "stroke-width=\"0.8\"/>\n",
      left, top, w, h);
  const std::vector<double> xt = round_ticks(xs.least, xs.most, 8);
  const std::vector<double> yt = round_ticks(ys.least, ys.most, 5);
  const double x_step = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
  const double y_step = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double v : xt)
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#ccc\" "
        "stroke-width=\"0.5\"/><text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\" "
        "font-size=\"11\">{4}</text>\n",
        px(v), top, top + h, top + h + 14, tick_text(v, x_step, plot.decimal_sign));
  for (double v : yt)
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#ccc\" "
        "stroke-width=\"0.5\"/><text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\" "
        "font-size=\"11\">{5}</text>\n",
        left, py(v), left + w, left - 4, py(v) + 4, tick_text(v, y_step, plot.decimal_sign));
  out += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"12\">{}</text>\n",
      left + w / 2, plot.height - 6.0, html_text(plot.x_label));
  out += fmt::format(
      "<text transform=\"translate(14 {:.1f}) rotate(-90)\" text-anchor=\"middle\" "
      "font-size=\"12\">{}</text>\n",
      top + h / 2, html_text(plot.y_label));
  // The series, then their legend.
  const int columns = static_cast<int>(w);
  double legend_x = left + 8;
  for (const SvgSeries& s : plot.series) {
    std::string points;
    for (const auto& [x, y] : column_extremes(s, xs.least, xs.most, columns))
      points += s.points
                    ? fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2.5\"/>", px(x), py(y))
                    : fmt::format("{:.2f},{:.2f} ", px(x), py(y));
    if (s.points)
      out += fmt::format("<g fill=\"{}\">{}</g>\n", s.color, points);
    else
      out += fmt::format(
          "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.2\" points=\"{}\"/>\n", s.color,
          points);
    if (s.label.empty()) continue;
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"2\"/><text x=\"{4:.1f}\" y=\"{5:.1f}\" font-size=\"11\">{6}</text>\n",
        legend_x, top + 12, legend_x + 18, s.color, legend_x + 22, top + 16, html_text(s.label));
    legend_x += 40 + 6.5 * static_cast<double>(s.label.size());
  }
  out += "</svg>\n";
  return out;
}

}  // namespace fl
