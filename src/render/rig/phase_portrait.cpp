#include "render/rig/phase_portrait.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "core/units.hpp"
#include "render/rig/force_overlay.hpp"
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

PhaseAxes phase_axes(const PhasePortraitState& state) {
  PhaseAxes axes;
  axes.x_range = std::max(1e-6, state.x_range);
  double top = 1e-3;
  if (state.theory) {
    const HarmonicMotion& c = *state.theory;
    top = std::max(top, std::hypot(c.x0 * c.omega, c.v0));
  }
  for (const Eigen::Vector3d& p : state.simulated)
    if (p.x() >= state.t - state.window && p.x() <= state.t) top = std::max(top, std::fabs(p.z()));
  axes.v_range = 1.15 * top;
  const double slip = std::fabs(state.slip_speed);
  if (slip > 0.0 && slip <= 2.5 * axes.v_range) {
    axes.slip_in_view = true;
    axes.v_range = std::max(axes.v_range, 1.1 * slip);
  }
  return axes;
}

void draw_phase_portrait(Overlay& o, const Rect& panel, float s, const PhasePortraitState& state) {
  const PhaseAxes axes = phase_axes(state);
  o.rect(panel, kPanel);
  o.text("v (mm/s) against x (mm)", Eigen::Vector2f(panel.x + 6 * s, panel.y + 4 * s), 11 * s,
         kSoft);
  // Room on the left for the speeds, below for the positions.
  const Rect area{panel.x + 34 * s, panel.y + 20 * s, panel.width - 40 * s, panel.height - 36 * s};
  o.rect_outline(area, 1.0f, kGrid);
  const auto to_pixel = [&](double x, double v) {
    const double fx = std::clamp((x + axes.x_range) / (2.0 * axes.x_range), 0.0, 1.0);
    const double fv = std::clamp((v + axes.v_range) / (2.0 * axes.v_range), 0.0, 1.0);
    return Eigen::Vector2f(
        area.x + 2.0f * s + static_cast<float>(fx) * (area.width - 4.0f * s),
        area.y + area.height - 2.0f * s - static_cast<float>(fv) * (area.height - 4.0f * s));
  };
  // The axes: speeds on the left (mm/s), positions below (mm), through zero.
  draw_value_axis(
      o, area, s, -axes.v_range * 1e3, axes.v_range * 1e3,
      [&](double mm_per_s) { return to_pixel(0.0, mm_per_s * 1e-3).y(); }, 10 * s);
  // The slip limit: dashed at +-v_r, or named under the right half when far off the scale.
  const double slip = std::fabs(state.slip_speed);
  const bool slip_named = !axes.slip_in_view && slip > 0.0;
  for (const AxisTick& tick : value_ticks(-axes.x_range * 1e3, axes.x_range * 1e3)) {
    const float x = to_pixel(tick.value * 1e-3, 0.0).x();
    o.line(Eigen::Vector2f(x, area.y), Eigen::Vector2f(x, area.y + area.height), 1.0f, kGrid);
    if (!slip_named || tick.value <= 0.0)
      o.text(tick.label, Eigen::Vector2f(x, area.y + area.height + 1 * s), 10 * s, kSoft,
             TextAlign::kCenter);
  }
  if (axes.slip_in_view) {
    for (const double v : {slip, -slip}) {
      const float y = to_pixel(0.0, v).y();
      std::vector<Eigen::Vector2f> line;
      for (float x = area.x; x <= area.x + area.width; x += 2.0f * s) line.emplace_back(x, y);
      o.dashed_polyline(line, 1.5f * s, kFrictionForceColor, 3, 2);
    }
    o.text("\xc2\xb1v_r", Eigen::Vector2f(area.x + area.width - 2 * s, to_pixel(0, slip).y()),
           10 * s, kFrictionForceColor, TextAlign::kRight);
  } else if (slip_named) {
    o.text(fmt::format("v_r {:.2g} m/s", slip),
           Eigen::Vector2f(panel.x + panel.width - 6 * s, area.y + area.height + 1 * s), 9 * s,
           kFrictionForceColor, TextAlign::kRight);
  }
  // The simulation over the window, a point every pixel or so, and where the plate is now.
  std::vector<Eigen::Vector2f> trace;
  for (const Eigen::Vector3d& p : state.simulated) {
    if (p.x() < state.t - state.window || p.x() > state.t) continue;
    const Eigen::Vector2f q = to_pixel(p.y(), p.z());
    if (!trace.empty() && (q - trace.back()).norm() < 1.0f && &p != &state.simulated.back())
      continue;
    trace.push_back(q);
  }
  o.polyline(trace, 1.5f * s, kWhite);
  // The theory's ellipse over it, dashed, a point every 3 degrees.
  if (state.theory && state.theory->omega > 0.0) {
    const double period = 2.0 * kPi / state.theory->omega;
    std::vector<Eigen::Vector2f> ellipse;
    for (int i = 0; i <= 120; ++i) {
      const double t = period * i / 120.0;
      ellipse.push_back(to_pixel(state.theory->at(t), state.theory->velocity_at(t)));
    }
    o.dashed_polyline(ellipse, 1.5f * s, kTheory);
  }
  if (!trace.empty()) o.dot(trace.back(), 2.5f * s, kWhite);
}

}  // namespace fl::render
