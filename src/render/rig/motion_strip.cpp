#include "render/rig/motion_strip.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/rig/overlay_palette.hpp"
#include "render/rig/rig_overlay.hpp"

namespace fl::render {
namespace {

using palette::kGrid;
using palette::kPanel;
using palette::kSoft;
using palette::kTheory;
using palette::kWhite;

}  // namespace

std::optional<double> position_at(std::span<const Eigen::Vector2d> simulated, double t) {
  if (simulated.empty()) return std::nullopt;
  if (t <= simulated.front().x()) return simulated.front().y();
  if (t >= simulated.back().x()) return simulated.back().y();
  const auto after =
      std::lower_bound(simulated.begin(), simulated.end(), t,
                       [](const Eigen::Vector2d& p, double time) { return p.x() < time; });
  const Eigen::Vector2d& b = *after;
  const Eigen::Vector2d& a = *(after - 1);
  const double span = b.x() - a.x();
  return span > 0.0 ? a.y() + (b.y() - a.y()) * (t - a.x()) / span : b.y();
}

void draw_motion_strip(Overlay& o, const Rect& panel, float s, const MotionStripState& state) {
  o.rect(panel, kPanel);
  o.text("plate x (mm) against t (s)", Eigen::Vector2f(panel.x + 6 * s, panel.y + 4 * s), 12 * s,
         kSoft);
  // The legend: the simulation, the theory, the estimator's turning points.
  // Room on the left for millimetres, below for the times and the theory's line.
  const Rect area{panel.x + 32 * s, panel.y + 21 * s, panel.width - 38 * s, panel.height - 50 * s};
  o.rect_outline(area, 1.0f, kGrid);
  const double t0 = state.t - state.window;
  const double range = std::max(1e-6, state.x_range);
  const auto x_of = [&](double t) {
    return area.x + area.width * static_cast<float>((t - t0) / state.window);
  };
  const auto y_of = [&](double x) {
    const double f = std::clamp((x + range) / (2.0 * range), 0.0, 1.0);
    return area.y + area.height - 2.0f * s - static_cast<float>(f) * (area.height - 4.0f * s);
  };
  // The axes: millimetres on the left, simulated time below.
  draw_value_axis(
      o, area, s, -range * 1e3, range * 1e3, [&](double mm) { return y_of(mm * 1e-3); }, 11 * s);
  draw_time_axis(o, area, s, t0, state.t);
  // The simulation: a point every pixel or so.
  std::vector<Eigen::Vector2f> trace;
  float last_x = -1e9f;
  for (const Eigen::Vector2d& p : state.simulated) {
    if (p.x() < t0 || p.x() > state.t) continue;
    const float x = x_of(p.x());
    if (x - last_x < 1.0f && &p != &state.simulated.back()) continue;
    trace.emplace_back(x, y_of(p.y()));
    last_x = x;
  }
  o.polyline(trace, 1.5f * s, kWhite);
  // The theory over it, dashed, every 2 pixels from t = 0.
  if (state.theory) {
    const double from = std::max(0.0, t0);
    const int points = std::max(2, static_cast<int>(area.width / (2.0f * s)));
    std::vector<Eigen::Vector2f> curve;
    for (int i = 0; i <= points; ++i) {
      const double t = t0 + state.window * static_cast<double>(i) / points;
      if (t >= from) curve.emplace_back(x_of(t), y_of(state.theory->at(t)));
    }
    o.dashed_polyline(curve, 1.5f * s, kTheory);
  }
  for (const double tp : state.turning_points) {
    if (tp < t0 || tp > state.t) continue;
    if (const auto x = position_at(state.simulated, tp))
      o.dot(Eigen::Vector2f(x_of(tp), y_of(*x)), 3.0f * s, palette::kPulse);
  }
  // The legend, right-aligned in the title row.
  float right = panel.x + panel.width - 6 * s;
  const auto entry = [&](const std::string& word, const Color& color, bool dot) {
    o.text(word, Eigen::Vector2f(right, panel.y + 4 * s), 11 * s, color, TextAlign::kRight);
    const Rect box = o.measure_text(word, 11 * s);
    const float mark_x = right - box.width - 5 * s;
    const float mark_y = panel.y + 4 * s + box.height / 2.0f;
    if (dot)
      o.dot(Eigen::Vector2f(mark_x, mark_y), 3.0f * s, color);
    else
      o.line(Eigen::Vector2f(mark_x - 8 * s, mark_y), Eigen::Vector2f(mark_x, mark_y), 1.5f * s,
             color);
    right = mark_x - (dot ? 3.0f : 8.0f) * s - 6 * s;
  };
  if (!state.turning_points.empty()) entry("turning", palette::kPulse, true);
  if (state.theory) entry("theory", kTheory, false);
  // Under the strip: what the theory is.
  if (!state.theory_label.empty())
    o.text(state.theory_label, Eigen::Vector2f(panel.x + 6 * s, panel.y + panel.height - 15 * s),
           11 * s, kTheory);
}

}  // namespace fl::render
