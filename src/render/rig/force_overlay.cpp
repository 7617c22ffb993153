#include "render/rig/force_overlay.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/rig/overlay_palette.hpp"

namespace fl::render {
namespace {

using palette::kGrid;
using palette::kPanel;
using palette::kSoft;
using palette::kWhite;

// The panel's layout at scale 1 (640x360).
constexpr float kPanelWidth = 138.0f;
constexpr float kBarTop = 20.0f;     // below the title
constexpr float kBarHeight = 44.0f;  // a share of 1
constexpr float kBarWidth = 22.0f;
constexpr float kLegendTop = 84.0f;  // the reference arrow's row
constexpr float kPanelHeight = 100.0f;

// The screen direction of a world direction at a world point, or nothing when the point is
// behind the camera or the direction looks straight at it.
std::optional<std::pair<Eigen::Vector2f, Eigen::Vector2f>> screen_ray(
    const Camera& camera, int width, int height, const Eigen::Vector3f& point,
    const Eigen::Vector3f& direction) {
  const auto a = project_to_pixel(camera, width, height, point);
  const auto b = project_to_pixel(camera, width, height, point + 0.001f * direction);
  if (!a || !b) return std::nullopt;
  const Eigen::Vector2f d = *b - *a;
  if (d.norm() < 1e-4f) return std::nullopt;
  return std::pair{*a, Eigen::Vector2f(d.normalized())};
}

// "0.1 N", "20 mN".
std::string force_text(double newtons) {
  if (newtons < 0.1 - 1e-12) return fmt::format("{:g} mN", newtons * 1e3);
  return fmt::format("{:g} N", newtons);
}

}  // namespace

ForceScale force_scale(const Camera& camera, int width, int height, const Eigen::Vector3f& centre,
                       double spacing, double weight) {
  ForceScale scale;
  const Eigen::Vector3f half(static_cast<float>(spacing / 2.0), 0.0f, 0.0f);
  const auto a = project_to_pixel(camera, width, height, centre - half);
  const auto b = project_to_pixel(camera, width, height, centre + half);
  const float spacing_pixels = a && b ? (*b - *a).norm() : 0.25f * static_cast<float>(width);
  const double reference = 0.35 * static_cast<double>(spacing_pixels);  // pixels, half the weight
  scale.pixels_per_newton = weight > 0.0 ? static_cast<float>(reference / (0.5 * weight)) : 100.0f;
  // The largest of 1, 2, 5 x 10^k newtons at most a quarter of the weight.
  const double target = weight > 0.0 ? 0.25 * weight : 0.1;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  scale.reference_force = decade;
  for (const double m : {2.0, 5.0})
    if (m * decade <= target * (1.0 + 1e-12)) scale.reference_force = m * decade;
  return scale;
}

std::vector<ForceArrow> force_arrows(const Camera& camera, int width, int height,
                                     const PlateForces& forces, const ForceScale& scale) {
  std::vector<ForceArrow> arrows;
  const Eigen::Vector3f up = forces.rig_to_world.linear() * Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f along = forces.rig_to_world.linear() * Eigen::Vector3f::UnitX();
  const auto add = [&](std::string label, const Eigen::Vector3f& point,
                       const Eigen::Vector3f& direction, double force, const Color& color,
                       ForceArrow::Label label_at) {
    const auto ray = screen_ray(camera, width, height, forces.rig_to_world * point, direction);
    if (!ray) return;
    const float length = static_cast<float>(force) * scale.pixels_per_newton;
    arrows.push_back(ForceArrow{std::move(label), ray->first, ray->first + ray->second * length,
                                color, label_at});
  };
  const char* normal_labels[2] = {"N\xe2\x82\x80", "N\xe2\x82\x81"};
  const char* friction_labels[2] = {"F\xe2\x82\x80", "F\xe2\x82\x81"};
  // The friction first, the normal forces last: drawn in this order, a normal force's arrow is
  // never cut by the friction arrow that starts at the same point.
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactForce& c = forces.rollers[k];
    if (c.touching)
      add(friction_labels[k], c.point, along, c.friction, kFrictionForceColor,
          ForceArrow::Label::kBelow);
  }
  const double net = forces.rollers[0].friction + forces.rollers[1].friction;
  if (forces.rollers[0].touching || forces.rollers[1].touching)
    add("F\xe2\x82\x80 + F\xe2\x82\x81", forces.centre, along, net, kNetFrictionColor,
        ForceArrow::Label::kAbove);
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactForce& c = forces.rollers[k];
    if (c.touching)
      add(normal_labels[k], c.point, up, c.normal, kNormalForceColor, ForceArrow::Label::kBeyond);
  }
  return arrows;
}

// The arrows' labels, in pixels at 640x360: the smallest that reads on a GIF of that size.
constexpr float kArrowLabelSize = 13.0f;

void draw_force_arrows(Overlay& o, float s, const std::vector<ForceArrow>& arrows) {
  // Dark outlines under every arrow first, so the arrows read over the red frame and the green
  // plate alike and no outline cuts another arrow; then the arrows in their order.
  const Color shade{0.0f, 0.0f, 0.0f, 0.55f};
  for (const ForceArrow& a : arrows) o.arrow(a.from, a.to, 4.5f * s, 7.0f * s, shade);
  for (const ForceArrow& a : arrows) o.arrow(a.from, a.to, 2.2f * s, 6.0f * s, a.color);
  for (const ForceArrow& a : arrows) {
    const Eigen::Vector2f d = a.to - a.from;
    const float length = d.norm();
    const Rect box = o.measure_text(a.label, kArrowLabelSize * s);
    Eigen::Vector2f at = a.to;  // the label's centre
    switch (a.label_at) {
      case ForceArrow::Label::kBeyond: {
        const Eigen::Vector2f dir =
            length >= 1.0f ? Eigen::Vector2f(d / length) : Eigen::Vector2f(0.0f, -1.0f);
        at += dir * (4.0f * s + 0.5f * std::max(box.width, box.height));
        break;
      }
      case ForceArrow::Label::kBelow:
        at.y() += 4.0f * s + 0.5f * box.height;
        break;
      case ForceArrow::Label::kAbove:
        at.y() -= 4.0f * s + 0.5f * box.height;
        break;
    }
    // On a dark patch: the label reads over the bright plate, the bricks and the floor alike.
    o.rect(Rect{at.x() - box.width / 2.0f - 3.0f * s, at.y() - box.height / 2.0f - 1.5f * s,
                box.width + 6.0f * s, box.height + 3.0f * s},
           Color{0.05f, 0.07f, 0.10f, 0.72f});
    o.text(a.label, Eigen::Vector2f(at.x(), at.y() - box.height / 2.0f), kArrowLabelSize * s,
           a.color, TextAlign::kCenter);
  }
}

std::optional<std::array<double, 2>> weight_shares(const PlateForces& forces) {
  const double n0 = forces.rollers[0].touching ? std::max(0.0, forces.rollers[0].normal) : 0.0;
  const double n1 = forces.rollers[1].touching ? std::max(0.0, forces.rollers[1].normal) : 0.0;
  if (!(n0 + n1 > 0.0)) return std::nullopt;
  return std::array<double, 2>{n0 / (n0 + n1), n1 / (n0 + n1)};
}

WeightBars weight_bars(const Eigen::Vector2f& top_left, float s) {
  WeightBars bars;
  for (int k = 0; k < 2; ++k)
    bars.full[static_cast<std::size_t>(k)] =
        Rect{top_left.x() + (14.0f + 64.0f * static_cast<float>(k)) * s, top_left.y() + kBarTop * s,
             kBarWidth * s, kBarHeight * s};
  return bars;
}

float draw_weight_share(Overlay& o, const Eigen::Vector2f& top_left, float s,
                        const PlateForces& forces, const ForceScale& scale) {
  const Rect panel{top_left.x(), top_left.y(), kPanelWidth * s, kPanelHeight * s};
  o.rect(panel, kPanel);
  o.text("weight on the rollers", Eigen::Vector2f(panel.x + 6 * s, panel.y + 4 * s), 12 * s, kSoft);
  const WeightBars bars = weight_bars(top_left, s);
  const auto shares = weight_shares(forces);
  const char* names[2] = {"N\xe2\x82\x80", "N\xe2\x82\x81"};
  for (std::size_t k = 0; k < 2; ++k) {
    const Rect& full = bars.full[k];
    o.rect_outline(full, 1.0f, kGrid);
    if (shares) {
      const float tall = static_cast<float>((*shares)[k]) * full.height;
      o.rect(Rect{full.x, full.y + full.height - tall, full.width, tall}, kNormalForceColor);
    }
    const float label_x = full.x + full.width + 4 * s;
    o.text(names[k], Eigen::Vector2f(label_x, full.y + 2 * s), 12 * s, kNormalForceColor);
    o.text(shares ? fmt::format("{:.0f} %", 100.0 * (*shares)[k]) : std::string("0 %"),
           Eigen::Vector2f(label_x, full.y + full.height - 14 * s), 12 * s, kWhite);
  }
  if (!shares)
    o.text("in the air", Eigen::Vector2f(panel.x + 6 * s, bars.full[0].y + 16 * s), 12 * s, kWhite);
  // Half the weight: where both bars stand at rest in the middle.
  const float half_y = bars.full[0].y + 0.5f * bars.full[0].height;
  for (const Rect& full : bars.full) {
    // Marks beside each bar, so they never cut its fill.
    o.line(Eigen::Vector2f(full.x - 4 * s, half_y), Eigen::Vector2f(full.x - 1 * s, half_y), 1.0f,
           kSoft);
    o.line(Eigen::Vector2f(full.x + full.width + 1 * s, half_y),
           Eigen::Vector2f(full.x + full.width + 3 * s, half_y), 1.0f, kSoft);
  }
  // The arrows' scale: a reference arrow of a round force.
  const float y = panel.y + kLegendTop * s;
  const float length = static_cast<float>(scale.reference_force) * scale.pixels_per_newton;
  const Rect words = o.text("arrows:", Eigen::Vector2f(panel.x + 6 * s, y - 7 * s), 11 * s, kSoft);
  const float x0 = words.x + words.width + 5 * s;
  o.arrow(Eigen::Vector2f(x0, y), Eigen::Vector2f(x0 + length, y), 2.2f * s, 6.0f * s, kSoft);
  o.text(force_text(scale.reference_force), Eigen::Vector2f(x0 + length + 4 * s, y - 7 * s), 11 * s,
         kSoft);
  return panel.height;
}

}  // namespace fl::render
