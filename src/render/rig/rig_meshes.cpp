#include "render/rig/rig_meshes.hpp"

#include <algorithm>
#include <cmath>

namespace fl::render {

Color material_color(const std::string& material) {
  struct Entry {
    const char* key;
    Color color;
  };
  // sRGB; the keys of the paper's Table I.
  static const Entry kColors[] = {
      {"lego", {0.0f, 0.52f, 0.17f, 1.0f}},  // a green LEGO baseplate
      {"paper", {0.95f, 0.95f, 0.92f, 1.0f}},
      {"polished-wood", {0.60f, 0.36f, 0.18f, 1.0f}},
      {"construction-wood", {0.82f, 0.67f, 0.45f, 1.0f}},
      {"iron", {0.42f, 0.43f, 0.46f, 1.0f}},
      {"plexiglas", {0.70f, 0.86f, 0.93f, 1.0f}},
      {"brass", {0.80f, 0.64f, 0.24f, 1.0f}},
      {"cardboard", {0.68f, 0.53f, 0.35f, 1.0f}},
      {"rigid-foam", {0.93f, 0.87f, 0.58f, 1.0f}},
      {"flexible-foam", {0.90f, 0.72f, 0.48f, 1.0f}},
  };
  for (const Entry& e : kColors)
    if (material == e.key) return e.color;
  return Color{0.60f, 0.60f, 0.62f, 1.0f};
}

namespace rig {
namespace {

float to_linear(float c) {
  return std::pow(c, 2.2f);
}
float to_srgb(float c) {
  return std::pow(std::clamp(c, 0.0f, 1.0f), 1.0f / 2.2f);
}

}  // namespace

Color mix_light(const Color& a, const Color& b, float f) {
  const auto m = [f](float x, float y) {
    return to_srgb((1.0f - f) * to_linear(x) + f * to_linear(y));
  };
  return Color{m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), 1.0f};
}

MeshData make_plain_cylinder(float radius, float length, int segments, const Color& color) {
  return make_patterned_cylinder(
      radius, length, segments, [&](float, float) { return color; }, color);
}

float smeared_mark(float phi0, float phi1, float width, double sweep) {
  constexpr int kFace = 12;
  const int n_sweep = sweep > 0.0 ? 48 : 1;
  int hits = 0;
  for (int i = 0; i < kFace; ++i) {
    const double phi =
        static_cast<double>(phi0) + static_cast<double>(phi1 - phi0) * (i + 0.5) / kFace;
    for (int j = 0; j < n_sweep; ++j) {
      const double s = n_sweep == 1 ? 0.0 : sweep * ((j + 0.5) / n_sweep - 0.5);
      const double d = std::remainder(phi - s, 2.0 * kPi);
      hits += std::fabs(d) <= static_cast<double>(width) / 2.0 ? 1 : 0;
    }
  }
  return static_cast<float>(hits) / static_cast<float>(kFace * n_sweep);
}

MeshData make_roller(float radius, float length, double sweep) {
  const Color tube{0.90f, 0.90f, 0.87f, 1.0f};
  const Color mark{0.45f, 0.04f, 0.03f, 1.0f};
  const Color card{0.80f, 0.70f, 0.52f, 1.0f};
  // A wide dark mark: smeared over the 80 degrees a roller turns at 1600 rpm in a 30 fps frame's
  // shutter, it stays a visible streak.
  constexpr float kMarkWidth = static_cast<float>(kPi / 3.0);
  // 42 sides (the mark spans seven); the tube's ends are hidden by the discs.
  MeshData m = make_patterned_cylinder(
      radius, length, 42,
      [&](float a0, float a1) {
        return mix_light(tube, mark, smeared_mark(a0, a1, kMarkWidth, sweep));
      },
      tube, false);
  // The card discs that cap the tube, with the mark drawn across them as well.
  const float disc_radius = radius + 0.0015f;
  const MeshData disc = make_patterned_cylinder(
      disc_radius, 0.001f, 42,
      [&](float a0, float a1) {
        return mix_light(card, mark, smeared_mark(a0, a1, kMarkWidth, sweep));
      },
      card);
  for (const float s : {-1.0f, 1.0f})
    m.append(disc, translation(Eigen::Vector3f(0.0f, s * (length / 2.0f + 0.0005f), 0.0f)));
  return m;
}

MeshData make_gear_blur(const assets::PartSpec& spec, const Color& color) {
  const assets::GearData& g = *spec.gear;
  const float ring = static_cast<float>(0.5 * (g.pitch_radius + g.outer_radius));
  MeshData m = make_plain_cylinder(ring, static_cast<float>(g.width), 32, color);
  const Color hub = mix_light(color, Color{0, 0, 0, 1}, 0.25f);
  m.append(make_plain_cylinder(0.0042f, static_cast<float>(g.hub_width), 12, hub));
  return m;
}

MeshData make_board(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, float z, float tile) {
  const Color a{0.80f, 0.79f, 0.76f, 1.0f};
  const Color b{0.74f, 0.73f, 0.70f, 1.0f};
  const Color edge{0.55f, 0.54f, 0.52f, 1.0f};
  MeshData m;
  const auto quad = [&m](const Eigen::Vector3f& p0, const Eigen::Vector3f& p1,
                         const Eigen::Vector3f& p2, const Eigen::Vector3f& p3,
                         const Eigen::Vector3f& normal, const Color& color) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const Eigen::Vector3f* p : {&p0, &p1, &p2, &p3}) {
      m.positions.push_back(*p);
      m.normals.push_back(normal);
      m.colors.push_back(color);
    }
    for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + k);
  };
  const int nx = std::max(1, static_cast<int>(std::lround((hi.x() - lo.x()) / tile)));
  const int ny = std::max(1, static_cast<int>(std::lround((hi.y() - lo.y()) / tile)));
  const float sx = (hi.x() - lo.x()) / static_cast<float>(nx);
  const float sy = (hi.y() - lo.y()) / static_cast<float>(ny);
  const Eigen::Vector3f up(0, 0, 1);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const float x0 = lo.x() + sx * static_cast<float>(i);
      const float y0 = lo.y() + sy * static_cast<float>(j);
      quad({x0, y0, z}, {x0 + sx, y0, z}, {x0 + sx, y0 + sy, z}, {x0, y0 + sy, z}, up,
           (i + j) % 2 == 0 ? a : b);
    }
  }
  const float d = z - 0.012f;
  quad({lo.x(), lo.y(), d}, {hi.x(), lo.y(), d}, {hi.x(), lo.y(), z}, {lo.x(), lo.y(), z},
       {0, -1, 0}, edge);
  quad({hi.x(), hi.y(), d}, {lo.x(), hi.y(), d}, {lo.x(), hi.y(), z}, {hi.x(), hi.y(), z},
       {0, 1, 0}, edge);
  quad({lo.x(), hi.y(), d}, {lo.x(), lo.y(), d}, {lo.x(), lo.y(), z}, {lo.x(), hi.y(), z},
       {-1, 0, 0}, edge);
  quad({hi.x(), lo.y(), d}, {hi.x(), hi.y(), d}, {hi.x(), hi.y(), z}, {hi.x(), lo.y(), z},
       {1, 0, 0}, edge);
  return m;
}

void add_axle_stands(MeshData& out, double x, double axle_z, double roller_length, float ground) {
  const Color stand{0.55f, 0.56f, 0.58f, 1.0f};
  const float height = static_cast<float>(axle_z) - ground;
  for (const float side : {-1.0f, 1.0f}) {
    const float y = side * static_cast<float>(0.5 * roller_length + 0.008);
    out.append(make_box(Eigen::Vector3f(0.008f, 0.006f, height), stand),
               translation(Eigen::Vector3f(static_cast<float>(x), y, ground + height / 2.0f)));
  }
}

void add_hall_sensor(MeshData& out, const Eigen::Vector3f& sensor, double plate_width,
                     float ground) {
  const Eigen::Vector3f& s = sensor;
  const Color chip{0.08f, 0.08f, 0.09f, 1.0f};
  const Color board{0.10f, 0.24f, 0.48f, 1.0f};
  const Color metal{0.62f, 0.63f, 0.66f, 1.0f};
  const float board_z = s.z() + 0.00075f + 0.0008f;
  out.append(make_box(Eigen::Vector3f(0.004f, 0.003f, 0.0015f), chip), translation(s));
  out.append(make_box(Eigen::Vector3f(0.022f, 0.018f, 0.0016f), board),
             translation(Eigen::Vector3f(s.x(), s.y(), board_z)));
  const float post_y = std::max(s.y() + 0.012f, static_cast<float>(0.5 * plate_width) + 0.014f);
  const float arm_z = board_z + 0.0008f + 0.0015f;
  const float arm_length = post_y - s.y();
  out.append(make_box(Eigen::Vector3f(0.006f, arm_length, 0.003f), metal),
             translation(Eigen::Vector3f(s.x(), s.y() + arm_length / 2.0f, arm_z)));
  const float post_height = arm_z + 0.0015f - ground;
  out.append(make_box(Eigen::Vector3f(0.006f, 0.006f, post_height), metal),
             translation(Eigen::Vector3f(s.x(), post_y, ground + post_height / 2.0f)));
}

void add_motor(MeshData& out, double x, double z, double gear_y, float ground) {
  const float radius = std::clamp(static_cast<float>(z) - ground - 0.001f, 0.005f, 0.012f);
  const float length = 0.036f;
  const float y0 = static_cast<float>(gear_y) + 0.008f;
  const Color can{0.74f, 0.75f, 0.77f, 1.0f};
  const Color end{0.15f, 0.15f, 0.17f, 1.0f};
  out.append(make_plain_cylinder(radius, length, 32, can),
             translation(Eigen::Vector3f(static_cast<float>(x), y0 + length / 2.0f,
                                         static_cast<float>(z))));
  out.append(make_plain_cylinder(radius * 0.8f, 0.004f, 32, end),
             translation(Eigen::Vector3f(static_cast<float>(x), y0 + length + 0.002f,
                                         static_cast<float>(z))));
}

}  // namespace rig
}  // namespace fl::render
