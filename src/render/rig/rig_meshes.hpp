// The rig's procedural meshes, the parts that are not LEGO meshes: patterned cylinders, the
// rollers with their smeared mark, a fast gear's blurred stand-in, the board, the Hall sensor on
// its post, the motor, the stands under a frameless rig's axles; and the plate's colour. In the
// rig's coordinates (x along the plate's motion, z up, metres), colours sRGB.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "assets/part_catalog.hpp"
#include "render/mesh_data.hpp"
#include "render/rig/rig_geometry.hpp"

namespace fl::render {

// The plate's colour for its material (sRGB); grey for a material not in the table.
Color material_color(const std::string& material);

namespace rig {

// a and b mixed in linear light (what a camera's exposure averages), f of b.
Color mix_light(const Color& a, const Color& b, float f);

// A cylinder along y (length, radius) whose side faces are coloured by `side(phi0, phi1)`, where
// phi is the angle about +y measured so that turning the part by theta adds theta to it (a side
// point is (r cos phi, y, -r sin phi)). Caps are plain `cap` (none when `caps` is false).
// Per-face colours, smooth normals.
template <class SideColor>
MeshData make_patterned_cylinder(float radius, float length, int segments, SideColor side,
                                 const Color& cap, bool caps = true) {
  MeshData m;
  const float half = length / 2.0f;
  const auto at = [&](int i) { return static_cast<float>(2.0 * kPi * i / segments); };
  for (int i = 0; i < segments; ++i) {
    const float a0 = at(i), a1 = at(i + 1);
    const Eigen::Vector3f n0(std::cos(a0), 0.0f, -std::sin(a0));
    const Eigen::Vector3f n1(std::cos(a1), 0.0f, -std::sin(a1));
    const Color c = side(a0, a1);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const Eigen::Vector3f corners[4] = {
        n0 * radius - Eigen::Vector3f(0, half, 0), n1 * radius - Eigen::Vector3f(0, half, 0),
        n1 * radius + Eigen::Vector3f(0, half, 0), n0 * radius + Eigen::Vector3f(0, half, 0)};
    const Eigen::Vector3f normals[4] = {n0, n1, n1, n0};
    for (int k = 0; k < 4; ++k) {
      m.positions.push_back(corners[k]);
      m.normals.push_back(normals[k]);
      m.colors.push_back(c);
    }
    for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + k);
  }
  for (const float s : {1.0f, -1.0f}) {
    if (!caps) break;
    const auto centre = static_cast<std::uint32_t>(m.positions.size());
    const Eigen::Vector3f n(0.0f, s, 0.0f);
    m.positions.emplace_back(0.0f, s * half, 0.0f);
    m.normals.push_back(n);
    m.colors.push_back(cap);
    for (int i = 0; i < segments; ++i) {
      m.positions.emplace_back(radius * std::cos(at(i)), s * half, -radius * std::sin(at(i)));
      m.normals.push_back(n);
      m.colors.push_back(cap);
    }
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = centre + 1 + static_cast<std::uint32_t>(i);
      const std::uint32_t b = centre + 1 + static_cast<std::uint32_t>((i + 1) % segments);
      if (s > 0)
        m.indices.insert(m.indices.end(), {centre, a, b});
      else
        m.indices.insert(m.indices.end(), {centre, b, a});
    }
  }
  return m;
}

// A cylinder along y in one colour, sides and caps.
MeshData make_plain_cylinder(float radius, float length, int segments, const Color& color);

// The fraction of [phi0, phi1] covered by a mark of `width` centred on phi = 0, smeared over
// `sweep` (the angle turned while the shutter is open, centred on the frame's instant).
float smeared_mark(float phi0, float phi1, float width, double sweep);

// A roller: the PVC tube with a dark mark along it, capped by card discs, smeared over `sweep`.
MeshData make_roller(float radius, float length, double sweep);

// What a fast gear looks like through a shutter: the teeth blur into a ring (a disc at the pitch
// radius), the hub stays.
MeshData make_gear_blur(const assets::PartSpec& spec, const Color& color);

// The board the rig stands on: a checkerboard of `tile` squares from `lo` to `hi` (x and y) at
// height z, 12 mm thick. Beyond it is the background: pixels that cost nothing to shade.
MeshData make_board(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, float z, float tile);

// The two plain stands an axle at (x, axle_z) rests on beyond a roller of `roller_length`, from
// the ground up (a rig without a LEGO frame), appended to `out`.
void add_axle_stands(MeshData& out, double x, double axle_z, double roller_length, float ground);

// The Hall sensor: the chip (centred on `sensor`) under its board, held by an arm from a post
// beside the path of a plate `plate_width` wide, standing on the ground; appended to `out`.
void add_hall_sensor(MeshData& out, const Eigen::Vector3f& sensor, double plate_width,
                     float ground);

// The motor: a can on the motor's shaft at (x, z), beyond its gear at `gear_y`, sized to clear
// the ground; appended to `out`.
void add_motor(MeshData& out, double x, double z, double gear_y, float ground);

}  // namespace rig
}  // namespace fl::render
