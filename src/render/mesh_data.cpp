#include "render/mesh_data.hpp"
#include "core/units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fl::render {

void MeshData::append(const MeshData& other, const Eigen::Affine3f& transform) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  const Eigen::Matrix3f normal_matrix = transform.linear().inverse().transpose();
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.push_back(transform * other.positions[i]);
    normals.push_back((normal_matrix * other.normals[i]).normalized());
    colors.push_back(other.colors[i]);
  }
  for (const std::uint32_t index : other.indices) indices.push_back(base + index);
}

void MeshData::validate() const {
  if (normals.size() != positions.size() || colors.size() != positions.size())
    throw std::invalid_argument("a mesh needs one normal and one colour per position (" +
                                std::to_string(positions.size()) + " positions, " +
                                std::to_string(normals.size()) + " normals, " +
                                std::to_string(colors.size()) + " colours)");
  if (indices.size() % 3 != 0)
    throw std::invalid_argument("a mesh's index count must be a multiple of 3, not " +
                                std::to_string(indices.size()));
  for (const std::uint32_t index : indices) {
    if (index >= positions.size())
      throw std::invalid_argument("a mesh index (" + std::to_string(index) +
                                  ") is past its last vertex (" + std::to_string(positions.size()) +
                                  ")");
  }
}

std::pair<Eigen::Vector3f, float> MeshData::bounding_sphere() const {
  if (positions.empty()) return {Eigen::Vector3f::Zero(), 0.0f};
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  for (const auto& p : positions) centre += p;
  centre /= static_cast<float>(positions.size());
  float radius = 0.0f;
  for (const auto& p : positions) radius = std::max(radius, (p - centre).norm());
  return {centre, radius};
}

namespace {

void add_quad(MeshData& m, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
              const Eigen::Vector3f& c, const Eigen::Vector3f& d, const Eigen::Vector3f& normal,
              const Color& color) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  for (const auto* p : {&a, &b, &c, &d}) {
    m.positions.push_back(*p);
    m.normals.push_back(normal);
    m.colors.push_back(color);
  }
  for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

}  // namespace

MeshData make_box(const Eigen::Vector3f& size, const Color& color) {
  MeshData m;
  const Eigen::Vector3f h = size / 2.0f;
  // Each face: its normal axis, and two in-plane axes u, v with u x v = normal.
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {1.0f, -1.0f}) {
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = sign;
      Eigen::Vector3f u = Eigen::Vector3f::Zero();
      Eigen::Vector3f v = Eigen::Vector3f::Zero();
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = 1.0f;
      if (sign < 0) std::swap(u, v);
      const Eigen::Vector3f c = n.cwiseProduct(h);
      const Eigen::Vector3f du = u.cwiseProduct(h);
      const Eigen::Vector3f dv = v.cwiseProduct(h);
      add_quad(m, c - du - dv, c + du - dv, c + du + dv, c - du + dv, n, color);
    }
  }
  return m;
}

MeshData make_cylinder(float radius, float length, int segments, const Color& color,
                       const Color& stripe) {
  if (segments < 3) throw std::invalid_argument("a cylinder needs at least 3 segments");
  MeshData m;
  const float half = length / 2.0f;
  const auto angle = [&](int i) {
    return 2.0f * static_cast<float>(kPi) * static_cast<float>(i) / static_cast<float>(segments);
  };
  // Sides: one quad per segment, smooth normals; the first segment carries the stripe colour.
  for (int i = 0; i < segments; ++i) {
    const float a0 = angle(i);
    const float a1 = angle(i + 1);
    const Eigen::Vector3f n0(std::cos(a0), 0.0f, std::sin(a0));
    const Eigen::Vector3f n1(std::cos(a1), 0.0f, std::sin(a1));
    const Color& c = (i == 0 && stripe.a > 0.0f) ? stripe : color;
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const Eigen::Vector3f corners[4] = {
        n0 * radius + Eigen::Vector3f(0, half, 0), n1 * radius + Eigen::Vector3f(0, half, 0),
        n1 * radius - Eigen::Vector3f(0, half, 0), n0 * radius - Eigen::Vector3f(0, half, 0)};
    const Eigen::Vector3f normals[4] = {n0, n1, n1, n0};
    for (int k = 0; k < 4; ++k) {
      m.positions.push_back(corners[k]);
      m.normals.push_back(normals[k]);
      m.colors.push_back(c);
    }
    for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + k);
  }
  // Caps: a fan around a centre vertex at y = +half and y = -half.
  for (const float side : {1.0f, -1.0f}) {
    const auto centre = static_cast<std::uint32_t>(m.positions.size());
    const Eigen::Vector3f n(0.0f, side, 0.0f);
    m.positions.emplace_back(0.0f, side * half, 0.0f);
    m.normals.push_back(n);
    m.colors.push_back(color);
    for (int i = 0; i < segments; ++i) {
      m.positions.emplace_back(radius * std::cos(angle(i)), side * half,
                               radius * std::sin(angle(i)));
      m.normals.push_back(n);
      m.colors.push_back(color);
    }
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = centre + 1 + static_cast<std::uint32_t>(i);
      const std::uint32_t b = centre + 1 + static_cast<std::uint32_t>((i + 1) % segments);
      // Counter-clockwise seen from outside (+y for the top cap).
      if (side > 0) {
        m.indices.insert(m.indices.end(), {centre, b, a});
      } else {
        m.indices.insert(m.indices.end(), {centre, a, b});
      }
    }
  }
  return m;
}

MeshData make_ground(float size, float tile, const Color& a, const Color& b) {
  if (tile <= 0.0f || size <= 0.0f) throw std::invalid_argument("ground size and tile must be > 0");
  MeshData m;
  const int n = std::max(1, static_cast<int>(std::lround(size / tile)));
  const float step = size / static_cast<float>(n);
  const float start = -size / 2.0f;
  const Eigen::Vector3f up(0.0f, 0.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float x0 = start + step * static_cast<float>(i);
      const float y0 = start + step * static_cast<float>(j);
      add_quad(m, Eigen::Vector3f(x0, y0, 0.0f), Eigen::Vector3f(x0 + step, y0, 0.0f),
               Eigen::Vector3f(x0 + step, y0 + step, 0.0f), Eigen::Vector3f(x0, y0 + step, 0.0f),
               up, (i + j) % 2 == 0 ? a : b);
    }
  }
  return m;
}

}  // namespace fl::render
