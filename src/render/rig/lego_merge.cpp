#include "render/rig/lego_merge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/rig/rig_geometry.hpp"
#include "render/rig/rig_model.hpp"

namespace fl::render {
namespace rig {
namespace {

constexpr float kEps = 2e-5f;     // m: a vertex on a face counts as on it
constexpr float kMargin = 5e-5f;  // m: strictly inside a body, away from its outer faces

bool inside(const Eigen::AlignedBox3f& box, const Eigen::Vector3f& p, float eps) {
  return (p.array() >= box.min().array() - eps).all() &&
         (p.array() <= box.max().array() + eps).all();
}

// A unit vector along a part's axis.
Eigen::Vector3f axis_vector(assets::Axis axis) {
  switch (axis) {
    case assets::Axis::kX:
      return Eigen::Vector3f::UnitX();
    case assets::Axis::kY:
      return Eigen::Vector3f::UnitY();
    case assets::Axis::kZ:
      break;
  }
  return Eigen::Vector3f::UnitZ();
}

}  // namespace

MeshData lego_mesh_data(const assets::PartMesh& part, const Color& color) {
  MeshData m;
  m.positions = part.positions;
  m.normals = part.normals;
  m.indices = part.indices;
  m.colors.reserve(part.colors.size());
  for (const auto& c : part.colors)
    m.colors.push_back(color.a > 0.0f ? color : Color{c[0], c[1], c[2], 1.0f});
  return m;
}

Color average_color(const assets::PartMesh& mesh) {
  double r = 0, g = 0, b = 0;
  for (const auto& c : mesh.colors) {
    r += static_cast<double>(c[0]);
    g += static_cast<double>(c[1]);
    b += static_cast<double>(c[2]);
  }
  const double n = std::max<std::size_t>(1, mesh.colors.size());
  return Color{static_cast<float>(r / n), static_cast<float>(g / n), static_cast<float>(b / n), 1};
}

std::optional<Eigen::AlignedBox3f> body_box(const assets::PartSpec& spec) {
  if (spec.plates <= 0) return std::nullopt;
  return Eigen::AlignedBox3f(
      Eigen::Vector3f(static_cast<float>(spec.bounds.min[0]),
                      static_cast<float>(spec.bounds.min[1]), 0.0f),
      Eigen::Vector3f(static_cast<float>(spec.bounds.max[0]),
                      static_cast<float>(spec.bounds.max[1]),
                      static_cast<float>(spec.plates * assets::kPlateHeight)));
}

Eigen::AlignedBox3f moved(const Eigen::AlignedBox3f& box, const Eigen::Affine3f& pose) {
  Eigen::AlignedBox3f out;
  for (int i = 0; i < 8; ++i)
    out.extend(pose * box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)));
  return out;
}

bool bottom_covered(const Eigen::AlignedBox3f& body, std::size_t self,
                    const std::vector<LegoPlacement>& parts, std::optional<float> ground_z) {
  const float bottom = body.min().z();
  if (ground_z && std::fabs(bottom - *ground_z) < kEps) return true;
  const Eigen::Vector2f lo = body.min().head<2>();
  const Eigen::Vector2f hi = body.max().head<2>();
  const int nx = std::max(2, static_cast<int>(std::ceil((hi.x() - lo.x()) / 0.001f)) + 1);
  const int ny = std::max(2, static_cast<int>(std::ceil((hi.y() - lo.y()) / 0.001f)) + 1);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const Eigen::Vector2f p(lo.x() + (hi.x() - lo.x()) * static_cast<float>(i) / (nx - 1),
                              lo.y() + (hi.y() - lo.y()) * static_cast<float>(j) / (ny - 1));
      bool covered = false;
      for (std::size_t k = 0; k < parts.size() && !covered; ++k) {
        if (k == self || !parts[k].body) continue;
        const Eigen::AlignedBox3f& b = *parts[k].body;
        // A neighbour below reaches within 0.2 mm of the edge of the grid's cell.
        covered = std::fabs(b.max().z() - bottom) < kEps &&
                  (p.array() >= b.min().head<2>().array() - 2.5e-4f).all() &&
                  (p.array() <= b.max().head<2>().array() + 2.5e-4f).all();
      }
      if (!covered) return false;
    }
  }
  return true;
}

MergedParts merge_visible(const std::vector<LegoPlacement>& parts, std::size_t* full,
                          std::size_t* drawn) {
  MergedParts merged;
  MeshData& out = merged.visible;
  const Color hole_dark{0.10f, 0.10f, 0.11f, 1.0f};
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const LegoPlacement& part = parts[p];
    const assets::PartMesh& mesh = *part.mesh;
    const Eigen::Matrix3f normal_matrix = part.pose.linear().inverse().transpose();
    std::vector<Eigen::Vector3f> world(mesh.positions.size());
    for (std::size_t i = 0; i < world.size(); ++i) world[i] = part.pose * mesh.positions[i];
    std::vector<std::uint32_t> remap(mesh.positions.size(),
                                     std::numeric_limits<std::uint32_t>::max());
    // Only the bodies that reach this part can hide any of it.
    Eigen::AlignedBox3f reach;
    for (const auto& v : world) reach.extend(v);
    std::vector<const Eigen::AlignedBox3f*> near;
    for (std::size_t q = 0; q < parts.size(); ++q) {
      if (q == p || !parts[q].body) continue;
      const Eigen::AlignedBox3f grown(parts[q].body->min().array() - kEps,
                                      parts[q].body->max().array() + kEps);
      if (grown.intersects(reach)) near.push_back(&*parts[q].body);
    }
    // The holes' axes in the world, and how far each reaches along it.
    struct WorldHole {
      Eigen::Vector3f centre;
      Eigen::Vector3f axis;
      float radius;
      float half_length;
    };
    std::vector<WorldHole> holes;
    if (part.spec != nullptr && part.body) {
      for (const assets::Hole& h : part.spec->holes) {
        const Eigen::Vector3f local_axis = axis_vector(h.axis);
        // Half the body's extent along each axis (its frame is centred in x and y).
        const Eigen::Vector3f extent(static_cast<float>(part.spec->bounds.max[0]),
                                     static_cast<float>(part.spec->bounds.max[1]),
                                     static_cast<float>(part.spec->plates * assets::kPlateHeight));
        holes.push_back({part.pose * vec(h.center), (part.pose.linear() * local_axis).normalized(),
                         static_cast<float>(h.diameter / 2.0), extent.dot(local_axis)});
      }
    }
    const auto hole_wall = [&](const Eigen::Vector3f* v) {
      for (const WorldHole& h : holes) {
        bool all = true;
        for (int k = 0; k < 3 && all; ++k) {
          const Eigen::Vector3f d = v[k] - h.centre;
          const float along = d.dot(h.axis);
          all = std::fabs((d - along * h.axis).norm() - h.radius) < kMargin &&
                std::fabs(along) < h.half_length + kEps;
        }
        if (all) return true;
      }
      return false;
    };
    const auto hidden = [&](const Eigen::Vector3f* v) {
      // Inside one other body (a triangle across two neighbours may show between them).
      for (const Eigen::AlignedBox3f* body : near) {
        if (inside(*body, v[0], kEps) && inside(*body, v[1], kEps) && inside(*body, v[2], kEps))
          return true;
      }
      if (hole_wall(v)) return true;
      if (!part.bottom_covered || !part.body) return false;
      const Eigen::AlignedBox3f& b = *part.body;
      bool in_cavity = true;
      bool on_bottom = true;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3f& x = v[k];
        in_cavity = in_cavity && x.x() > b.min().x() + kMargin && x.x() < b.max().x() - kMargin &&
                    x.y() > b.min().y() + kMargin && x.y() < b.max().y() - kMargin &&
                    x.z() > b.min().z() - kEps && x.z() < b.max().z() - kMargin;
        on_bottom = on_bottom && std::fabs(x.z() - b.min().z()) < kEps;
      }
      return in_cavity || on_bottom;
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const Eigen::Vector3f v[3] = {world[mesh.indices[t]], world[mesh.indices[t + 1]],
                                    world[mesh.indices[t + 2]]};
      ++*full;
      if (hidden(v)) continue;
      ++*drawn;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t i = mesh.indices[t + static_cast<std::size_t>(k)];
        if (remap[i] == std::numeric_limits<std::uint32_t>::max()) {
          remap[i] = static_cast<std::uint32_t>(out.positions.size());
          out.positions.push_back(world[i]);
          out.normals.push_back((normal_matrix * mesh.normals[i]).normalized());
          const auto& c = mesh.colors[i];
          out.colors.push_back(part.color.a > 0.0f ? part.color : Color{c[0], c[1], c[2], 1.0f});
        }
        out.indices.push_back(remap[i]);
      }
    }

    // The shadow caster.
    if (!part.body) {
      MeshData own;
      own.positions = mesh.positions;
      own.normals = mesh.normals;
      own.indices = mesh.indices;
      own.colors.assign(mesh.positions.size(), hole_dark);
      merged.shadow.append(own, part.pose);
      continue;
    }
    constexpr float kInset = 2e-4f;  // m inside the drawn faces
    const Eigen::AlignedBox3f& b = *part.body;
    const Eigen::Vector3f size = b.sizes() - Eigen::Vector3f::Constant(2.0f * kInset);
    merged.shadow.append(make_box(size, hole_dark), translation(b.center()));
  }
  return merged;
}

}  // namespace rig

std::size_t cull_back_faces(RigModel& model, const Eigen::Vector3f& eye) {
  std::size_t removed = 0;
  for (const RigPart& part : model.parts) {
    if (part.body != RigPart::Body::kWorld || part.casts_shadow) continue;
    MeshData& mesh = model.meshes[part.mesh];
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const Eigen::Vector3f a = part.local * mesh.positions[mesh.indices[t]];
      const Eigen::Vector3f b = part.local * mesh.positions[mesh.indices[t + 1]];
      const Eigen::Vector3f c = part.local * mesh.positions[mesh.indices[t + 2]];
      if ((b - a).cross(c - a).dot(eye - a) <= 0.0f) {
        ++removed;
        continue;
      }
      kept.insert(kept.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    }
    mesh.indices = std::move(kept);
  }
  return removed;
}

}  // namespace fl::render
