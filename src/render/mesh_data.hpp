// Triangle meshes on the CPU side: positions, normals, per-vertex colours and indices, in the
// part's own frame (metres). The renderer uploads them once and draws them with a model matrix.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fl::render {

// A colour in sRGB, components 0..1 (a = opacity, used by the 2D overlay).
struct Color {
  float r = 1.0f;
  float g = 1.0f;
  float b = 1.0f;
  float a = 1.0f;
};

struct MeshData {
  std::vector<Eigen::Vector3f> positions;  // m
  std::vector<Eigen::Vector3f> normals;    // unit length, one per position
  std::vector<Color> colors;               // one per position
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside

  std::size_t triangle_count() const { return indices.size() / 3; }
  // Appends `other` moved by `transform` (for merging static parts into one draw).
  void append(const MeshData& other,
              const Eigen::Affine3f& transform = Eigen::Affine3f::Identity());
  // Throws std::invalid_argument if the arrays disagree or an index is out of range.
  void validate() const;
  // The smallest sphere around the centroid that holds every vertex: {centre, radius}.
  std::pair<Eigen::Vector3f, float> bounding_sphere() const;
};

// A box of the given size (m) centred on the origin, flat-shaded faces.
MeshData make_box(const Eigen::Vector3f& size, const Color& color);

// A cylinder along y, centred on the origin, with `segments` flat sides (smooth normals) and
// caps; `stripe` (if its alpha > 0) colours one side strip so that turning shows.
MeshData make_cylinder(float radius, float length, int segments, const Color& color,
                       const Color& stripe = Color{0, 0, 0, 0});

// A square ground plane at z = 0, `size` m across, in tiles of `tile` m alternating two colours.
MeshData make_ground(float size, float tile, const Color& a, const Color& b);

}  // namespace fl::render
