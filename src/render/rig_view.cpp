#include "render/rig_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "scene/drive_layout.hpp"

namespace fl::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kEps = 2e-5f;     // m: a vertex on a face counts as on it
constexpr float kMargin = 5e-5f;  // m: strictly inside a body, away from its outer faces

Eigen::Vector3f vec(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

Eigen::Affine3f translation(const Eigen::Vector3f& at) {
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(at);
  return t;
}

Eigen::Affine3f about_z(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitZ()));
}

Eigen::Affine3f about_y(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitY()));
}

Eigen::Affine3f about_x(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitX()));
}

double degrees_to_radians(int degrees) {
  return degrees * kPi / 180.0;
}

float to_linear(float c) {
  return std::pow(c, 2.2f);
}
float to_srgb(float c) {
  return std::pow(std::clamp(c, 0.0f, 1.0f), 1.0f / 2.2f);
}
// a and b mixed in linear light (what a camera's exposure averages), f of b.
Color mix_light(const Color& a, const Color& b, float f) {
  const auto m = [f](float x, float y) {
    return to_srgb((1.0f - f) * to_linear(x) + f * to_linear(y));
  };
  return Color{m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), 1.0f};
}

Color rgb(const std::array<float, 3>& c) {
  return Color{c[0], c[1], c[2], 1.0f};
}

// A LEGO mesh as MeshData, in `color` (or its own colours when color.a == 0).
MeshData to_mesh_data(const assets::PartMesh& part, const Color& color) {
  MeshData m;
  m.positions = part.positions;
  m.normals = part.normals;
  m.indices = part.indices;
  m.colors.reserve(part.colors.size());
  for (const auto& c : part.colors)
    m.colors.push_back(color.a > 0.0f ? color : Color{c[0], c[1], c[2], 1.0f});
  return m;
}

// The body of a brick, plate or Technic brick (studs not included), in its own frame: the
// region its cavity and studs hide in.
std::optional<Eigen::AlignedBox3f> body_box(const assets::PartSpec& spec) {
  if (spec.plates <= 0) return std::nullopt;
  return Eigen::AlignedBox3f(
      Eigen::Vector3f(static_cast<float>(spec.bounds.min[0]),
                      static_cast<float>(spec.bounds.min[1]), 0.0f),
      Eigen::Vector3f(static_cast<float>(spec.bounds.max[0]),
                      static_cast<float>(spec.bounds.max[1]),
                      static_cast<float>(spec.plates * assets::kPlateHeight)));
}

// A box moved by a pose that turns by multiples of 90 degrees about z (stays axis-aligned).
Eigen::AlignedBox3f moved(const Eigen::AlignedBox3f& box, const Eigen::Affine3f& pose) {
  Eigen::AlignedBox3f out;
  for (int i = 0; i < 8; ++i)
    out.extend(pose * box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)));
  return out;
}

bool inside(const Eigen::AlignedBox3f& box, const Eigen::Vector3f& p, float eps) {
  return (p.array() >= box.min().array() - eps).all() &&
         (p.array() <= box.max().array() + eps).all();
}

// A part placed on the grid (frame parts, the plate's blocks), before merging.
struct Placed {
  const assets::PartSpec* spec = nullptr;
  std::shared_ptr<const assets::PartMesh> mesh;
  Eigen::Affine3f pose = Eigen::Affine3f::Identity();
  Color color{0, 0, 0, 0};                  // a = 0: the mesh's own colours
  std::optional<Eigen::AlignedBox3f> body;  // in the merged mesh's frame
  bool bottom_covered = false;
};

// Whether something covers the whole underside of `body`: the ground, or bodies whose tops lie
// in its bottom plane (checked on a 1 mm grid over its footprint).
bool bottom_covered(const Eigen::AlignedBox3f& body, std::size_t self,
                    const std::vector<Placed>& parts, std::optional<float> ground_z) {
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

// The parts merged, as drawn (`visible`) and as they cast shadows (`shadow`).
struct MergedParts {
  MeshData visible;
  MeshData shadow;
};

// Merges the parts into one mesh, leaving out the triangles no camera above the ground can see:
// those inside another part's body (studs under the brick above, a top face under a brick) and,
// for a part whose underside is covered, those of its cavity (inner walls, tubes, the underside
// of its top) and of its bottom rim; and the walls of Technic holes, whose inside shows the
// shadow caster instead (a dark box, like a hole's depth).
//
// The shadow caster of a part with a body is that body shrunk by 0.2 mm: it lies inside the
// drawn part (so the camera never sees it, but through a hole), casts the same shadow but for
// the studs' (a few pixels at 720p), and is 12 triangles instead of hundreds. A part without a
// body casts its own mesh.
MergedParts merge_visible(const std::vector<Placed>& parts, std::size_t* full, std::size_t* drawn) {
  MergedParts merged;
  MeshData& out = merged.visible;
  const Color hole_dark{0.10f, 0.10f, 0.11f, 1.0f};
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Placed& part = parts[p];
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

// The fraction of [phi0, phi1] covered by a mark of `width` centred on phi = 0, smeared over
// `sweep` (the angle turned while the shutter is open, centred on the frame's instant).
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

// A roller: the PVC tube with a dark mark along it, capped by card discs, smeared over `sweep`.
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

// What a fast gear looks like through a shutter: the teeth blur into a ring (a disc at the pitch
// radius), the hub stays.
MeshData make_gear_blur(const assets::PartSpec& spec, const Color& color) {
  const assets::GearData& g = *spec.gear;
  const float ring = static_cast<float>(0.5 * (g.pitch_radius + g.outer_radius));
  const auto plain = [&](float, float) { return color; };
  MeshData m = make_patterned_cylinder(ring, static_cast<float>(g.width), 32, plain, color);
  const Color hub = mix_light(color, Color{0, 0, 0, 1}, 0.25f);
  m.append(make_patterned_cylinder(
      0.0042f, static_cast<float>(g.hub_width), 12, [&](float, float) { return hub; }, hub));
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

// The board the rig stands on: a checkerboard of `tile` squares from `lo` to `hi` (x and y) at
// height z, 12 mm thick. Beyond it is the background: pixels that cost nothing to shade.
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

const assets::PartSpec& need_part(const assets::PartCatalog* catalog, const std::string& name) {
  if (catalog == nullptr)
    throw std::invalid_argument("drawing the rig needs the LEGO part index for '" + name + "'");
  const assets::PartSpec* spec = catalog->find(name);
  if (spec == nullptr)
    throw std::invalid_argument("the LEGO part index has no part '" + name + "'");
  return *spec;
}

RigPart make_part(std::size_t mesh, RigPart::Body body, int shaft = 0) {
  RigPart part;
  part.mesh = mesh;
  part.body = body;
  part.shaft = shaft;
  return part;
}

// The angle, in the x-z plane, of the direction from (x0, z0) to (x1, z1), measured like a
// turn about +y (so that a turn by theta adds theta).
double direction_about_y(double x0, double z0, double x1, double z1) {
  return std::atan2(-(z1 - z0), x1 - x0);
}

class ModelBuilder {
 public:
  ModelBuilder(const Scene& scene, const assets::PartCatalog* catalog, assets::MeshLibrary* meshes)
      : scene_(scene), catalog_(catalog), meshes_(meshes) {}

  RigModel build();

 private:
  std::size_t add_mesh(MeshData mesh) {
    model_.meshes.push_back(std::move(mesh));
    return model_.meshes.size() - 1;
  }
  std::shared_ptr<const assets::PartMesh> load(const assets::PartSpec& spec) {
    if (meshes_ == nullptr)
      throw std::invalid_argument("drawing the rig's LEGO parts needs a mesh library");
    return meshes_->load(spec);
  }
  void add_shafts();
  void add_static();
  void add_plate();
  void add_rollers_and_axles();
  void add_gears();
  void finish_bounds();

  const Scene& scene_;
  const assets::PartCatalog* catalog_;
  assets::MeshLibrary* meshes_;
  RigModel model_;
  std::optional<DriveLayout> layout_;
  MeshData static_extra_;  // the sensor's board, stands, the motor: merged with the frame
};

void ModelBuilder::add_shafts() {
  const double l = scene_.rollers.spacing;
  const double a = scene_.rollers.radius;
  if (scene_.drive) {
    layout_ = drive_layout(scene_);
    for (const ShaftPlacement& s : layout_->shafts) model_.shafts.push_back({s.role, s.x, s.z});
  } else {
    model_.shafts.push_back({"roller 0", -0.5 * l, -a});
    model_.shafts.push_back({"roller 1", 0.5 * l, -a});
  }
}

void ModelBuilder::add_static() {
  // The frame's LEGO parts, merged into one mesh.
  std::vector<Placed> parts;
  if (scene_.frame) {
    for (const FramePart& fp : scene_.frame->parts) {
      const assets::PartSpec& spec = need_part(catalog_, fp.part);
      Placed p;
      p.spec = &spec;
      p.mesh = load(spec);
      p.pose = translation(vec(fp.position)) * about_z(degrees_to_radians(fp.turn));
      p.color = rgb(fp.color);
      if (auto body = body_box(spec)) p.body = moved(*body, p.pose);
      parts.push_back(std::move(p));
    }
  }
  // The ground: the frame's lowest face (the table it stands on), else below the lowest part.
  const double a = scene_.rollers.radius;
  float ground = static_cast<float>(-2.0 * a - 0.03);
  if (!parts.empty()) {
    ground = std::numeric_limits<float>::max();
    for (const Placed& p : parts) {
      for (const auto& v : p.mesh->positions) ground = std::min(ground, (p.pose * v).z());
    }
  } else if (layout_) {
    for (const GearPlacement& g : layout_->gears) {
      const double r = scene_.drive->gear(g.teeth).pitch_radius + 0.001;
      ground = std::min(ground, static_cast<float>(model_.shafts[g.shaft].z - r - 0.01));
    }
  }
  model_.ground_z = ground;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].body) parts[i].bottom_covered = bottom_covered(*parts[i].body, i, parts, ground);
  model_.stats.frame_parts = parts.size();
  MergedParts frame =
      merge_visible(parts, &model_.stats.frame_triangles_full, &model_.stats.frame_triangles_drawn);

  // Without a frame, the rollers' axles rest on two plain stands each.
  if (!scene_.frame) {
    const Color stand{0.55f, 0.56f, 0.58f, 1.0f};
    for (int k = 0; k < 2; ++k) {
      const RigShaft& s = model_.shafts[static_cast<std::size_t>(k)];
      const float height = static_cast<float>(s.z) - ground;
      for (const float side : {-1.0f, 1.0f}) {
        const float y = side * static_cast<float>(0.5 * scene_.rollers.length + 0.008);
        static_extra_.append(
            make_box(Eigen::Vector3f(0.008f, 0.006f, height), stand),
            translation(Eigen::Vector3f(static_cast<float>(s.x), y, ground + height / 2.0f)));
      }
    }
  }

  // The Hall sensor: the chip (centred on the sensor's position) under its board, held by an
  // arm from a post beside the plate's path.
  if (scene_.sensor) {
    const Eigen::Vector3f s = vec(scene_.sensor->position);
    model_.sensor = s;
    const Color chip{0.08f, 0.08f, 0.09f, 1.0f};
    const Color board{0.10f, 0.24f, 0.48f, 1.0f};
    const Color metal{0.62f, 0.63f, 0.66f, 1.0f};
    const float board_z = s.z() + 0.00075f + 0.0008f;
    static_extra_.append(make_box(Eigen::Vector3f(0.004f, 0.003f, 0.0015f), chip), translation(s));
    static_extra_.append(make_box(Eigen::Vector3f(0.022f, 0.018f, 0.0016f), board),
                         translation(Eigen::Vector3f(s.x(), s.y(), board_z)));
    const float post_y =
        std::max(s.y() + 0.012f, static_cast<float>(0.5 * scene_.plate.width) + 0.014f);
    const float arm_z = board_z + 0.0008f + 0.0015f;
    const float arm_length = post_y - s.y();
    static_extra_.append(make_box(Eigen::Vector3f(0.006f, arm_length, 0.003f), metal),
                         translation(Eigen::Vector3f(s.x(), s.y() + arm_length / 2.0f, arm_z)));
    const float post_height = arm_z + 0.0015f - ground;
    static_extra_.append(make_box(Eigen::Vector3f(0.006f, 0.006f, post_height), metal),
                         translation(Eigen::Vector3f(s.x(), post_y, ground + post_height / 2.0f)));
  }

  // The motor: a can on its shaft, beyond its gear.
  if (layout_) {
    const RigShaft& m = model_.shafts[static_cast<std::size_t>(layout_->motor)];
    double gear_y = 0.5 * scene_.rollers.length;
    for (const GearPlacement& g : layout_->gears)
      if (g.shaft == layout_->motor) gear_y = std::max(gear_y, g.y);
    const float radius = std::clamp(static_cast<float>(m.z) - ground - 0.001f, 0.005f, 0.012f);
    const float length = 0.036f;
    const float y0 = static_cast<float>(gear_y) + 0.008f;
    const Color can{0.74f, 0.75f, 0.77f, 1.0f};
    const Color end{0.15f, 0.15f, 0.17f, 1.0f};
    const auto plain = [&](float, float) { return can; };
    static_extra_.append(make_patterned_cylinder(radius, length, 32, plain, can),
                         translation(Eigen::Vector3f(static_cast<float>(m.x), y0 + length / 2.0f,
                                                     static_cast<float>(m.z))));
    static_extra_.append(make_patterned_cylinder(
                             radius * 0.8f, 0.004f, 32, [&](float, float) { return end; }, end),
                         translation(Eigen::Vector3f(static_cast<float>(m.x), y0 + length + 0.002f,
                                                     static_cast<float>(m.z))));
  }

  // Drawn without casting shadows, then the casters (inside them), then the simple parts.
  if (!frame.visible.indices.empty()) {
    RigPart drawn = make_part(add_mesh(std::move(frame.visible)), RigPart::Body::kWorld);
    drawn.casts_shadow = false;
    model_.parts.push_back(drawn);
    model_.parts.push_back(make_part(add_mesh(std::move(frame.shadow)), RigPart::Body::kWorld));
  }
  if (!static_extra_.indices.empty())
    model_.parts.push_back(make_part(add_mesh(std::move(static_extra_)), RigPart::Body::kWorld));
}

void ModelBuilder::add_plate() {
  const PlateDesc& p = scene_.plate;
  const PlateMass mass = plate_mass(scene_);
  const float x_c = static_cast<float>(mass.x_c);
  const float bottom = static_cast<float>(-mass.h_c);
  const float top = bottom + static_cast<float>(p.thickness);
  MeshData plate =
      make_box(Eigen::Vector3f(static_cast<float>(p.length), static_cast<float>(p.width),
                               static_cast<float>(p.thickness)),
               material_color(p.material));
  for (auto& v : plate.positions) v += Eigen::Vector3f(-x_c, 0.0f, bottom + (top - bottom) / 2.0f);
  // The blocks on its top (their cavities face the plate: left out).
  std::vector<Placed> blocks;
  for (const PlateBlock& b : p.blocks) {
    const assets::PartSpec& spec = need_part(catalog_, b.part);
    Placed placed;
    placed.spec = &spec;
    placed.mesh = load(spec);
    placed.pose =
        translation(Eigen::Vector3f(static_cast<float>(b.x) - x_c, static_cast<float>(b.y), top)) *
        about_z(degrees_to_radians(b.turn));
    if (auto body = body_box(spec)) placed.body = moved(*body, placed.pose);
    placed.bottom_covered = true;
    blocks.push_back(std::move(placed));
  }
  std::size_t full = 0, drawn = 0;
  MergedParts merged = merge_visible(blocks, &full, &drawn);
  // The magnets: nickel-plated discs, magnetised along z.
  const Color nickel{0.80f, 0.80f, 0.83f, 1.0f};
  for (const MagnetDesc& m : scene_.magnets) {
    const auto plain = [&](float, float) { return nickel; };
    plate.append(
        make_patterned_cylinder(static_cast<float>(m.diameter / 2.0),
                                static_cast<float>(m.thickness), 24, plain, nickel),
        translation(Eigen::Vector3f(static_cast<float>(m.x) - x_c, 0.0f,
                                    top + static_cast<float>(m.height + m.thickness / 2.0))) *
            about_x(kPi / 2.0));
  }
  // The blocks as drawn, then the slab, the magnets and the blocks' shadow casters.
  if (!merged.visible.indices.empty()) {
    RigPart drawn_blocks = make_part(add_mesh(std::move(merged.visible)), RigPart::Body::kPlate);
    drawn_blocks.casts_shadow = false;
    model_.parts.push_back(drawn_blocks);
  }
  plate.append(merged.shadow);
  model_.parts.push_back(make_part(add_mesh(std::move(plate)), RigPart::Body::kPlate));

  // The magnet nearest the sensor, at rest (the sensor camera looks at it).
  const RigPose rest = rest_pose(scene_);
  double best = std::numeric_limits<double>::infinity();
  for (const MagnetDesc& m : scene_.magnets) {
    const Eigen::Vector3f at =
        plate_transform(rest) * Eigen::Vector3f(static_cast<float>(m.x) - x_c, 0.0f,
                                                top + static_cast<float>(m.height + m.thickness));
    const double d = (at - model_.sensor).norm();
    if (d < best) {
      best = d;
      model_.magnet = at;
    }
  }
  if (scene_.magnets.empty()) model_.magnet = model_.sensor;
}

void ModelBuilder::add_rollers_and_axles() {
  const float a = static_cast<float>(scene_.rollers.radius);
  const float length = static_cast<float>(scene_.rollers.length);
  // The rollers, in every blur level.
  std::vector<std::size_t> variants;
  for (const double sweep : kBlurSweeps)
    variants.push_back(add_mesh(make_roller(a, length, sweep)));
  for (int k = 0; k < 2; ++k) {
    RigPart part = make_part(variants[0], RigPart::Body::kShaft, k);
    part.blur_variants = variants;
    // The second roller's mark starts on the other side, so the two never look alike.
    part.phase = k == 0 ? 0.0 : kPi;
    model_.parts.push_back(part);
  }
  // An axle through each shaft, across its gears (and the frame, for the rollers).
  const assets::PartSpec* axle =
      catalog_ != nullptr && scene_uses_parts(scene_) ? catalog_->find("axle-12") : nullptr;
  std::size_t axle_mesh = 0;
  float axle_length = 1.0f;
  if (axle != nullptr && axle->axle) {
    axle_mesh = add_mesh(to_mesh_data(*load(*axle), Color{0.10f, 0.10f, 0.11f, 1.0f}));
    axle_length = static_cast<float>(axle->axle->length);
  } else {
    const Color dark{0.12f, 0.12f, 0.13f, 1.0f};
    axle_mesh = add_mesh(make_patterned_cylinder(
        0.0024f, 1.0f, 12, [&](float, float) { return dark; }, dark));
  }
  for (std::size_t s = 0; s < model_.shafts.size(); ++s) {
    float y0 = std::numeric_limits<float>::max();
    float y1 = std::numeric_limits<float>::lowest();
    if (s < 2) {
      y0 = -length / 2.0f - 0.012f;
      y1 = length / 2.0f + 0.012f;
    }
    if (layout_) {
      for (const GearPlacement& g : layout_->gears) {
        if (static_cast<std::size_t>(g.shaft) != s) continue;
        y0 = std::min(y0, static_cast<float>(g.y) - 0.006f);
        y1 = std::max(y1, static_cast<float>(g.y) + 0.006f);
      }
      if (static_cast<int>(s) == layout_->motor) y1 += 0.006f;
    }
    if (y1 <= y0) continue;
    Eigen::Affine3f local = translation(Eigen::Vector3f(0.0f, (y0 + y1) / 2.0f, 0.0f));
    local.scale(Eigen::Vector3f(1.0f, (y1 - y0) / axle_length, 1.0f));
    RigPart part = make_part(axle_mesh, RigPart::Body::kShaft, static_cast<int>(s));
    part.local = local;
    model_.parts.push_back(part);
  }
}

void ModelBuilder::add_gears() {
  if (!layout_) return;
  // One mesh (and one blurred stand-in) per tooth count, shared by every gear of that count.
  std::map<int, std::pair<std::size_t, std::size_t>> by_teeth;
  for (const GearPlacement& g : layout_->gears) {
    if (by_teeth.count(g.teeth) != 0) continue;
    const assets::PartSpec& spec = need_part(catalog_, "gear-" + std::to_string(g.teeth));
    if (!spec.gear) throw std::invalid_argument("the part '" + spec.name + "' is not a gear");
    const auto mesh = load(spec);
    const std::size_t sharp = add_mesh(to_mesh_data(*mesh, Color{0, 0, 0, 0}));
    const std::size_t blur = add_mesh(make_gear_blur(spec, average_color(*mesh)));
    by_teeth[g.teeth] = {sharp, blur};
  }
  // Teeth interleave: along the chain from the motor, each driven gear's phase puts a gap
  // where its driver's tooth points at it (tooth 0 lies on the part's +x).
  std::vector<double> phase(layout_->gears.size(), 0.0);
  for (const GearMesh& m : layout_->meshes) {
    const GearPlacement& a = layout_->gears[static_cast<std::size_t>(m.driver)];
    const GearPlacement& b = layout_->gears[static_cast<std::size_t>(m.driven)];
    const RigShaft& sa = model_.shafts[static_cast<std::size_t>(a.shaft)];
    const RigShaft& sb = model_.shafts[static_cast<std::size_t>(b.shaft)];
    const double alpha = direction_about_y(sa.x, sa.z, sb.x, sb.z);
    const double ratio = static_cast<double>(a.teeth) / b.teeth;
    phase[static_cast<std::size_t>(m.driven)] =
        alpha + kPi - kPi / b.teeth + ratio * (alpha - phase[static_cast<std::size_t>(m.driver)]);
  }
  for (std::size_t i = 0; i < layout_->gears.size(); ++i) {
    const GearPlacement& g = layout_->gears[i];
    const auto [sharp, blur] = by_teeth.at(g.teeth);
    RigPart part = make_part(sharp, RigPart::Body::kShaft, g.shaft);
    part.phase = phase[i];
    part.local = translation(Eigen::Vector3f(0.0f, static_cast<float>(g.y), 0.0f));
    // Through a shutter a gear's teeth blur once it turns by two teeth in an exposure.
    const double tooth = 2.0 * kPi / g.teeth;
    for (const double sweep : kBlurSweeps)
      part.blur_variants.push_back(sweep >= 2.0 * tooth ? blur : sharp);
    model_.parts.push_back(part);
  }
}

void ModelBuilder::finish_bounds() {
  RigPose pose = rest_pose(scene_);
  double amplitude = std::fabs(scene_.plate.offset);
  try {
    amplitude = std::max(amplitude, initial_amplitude(scene_, scene_.friction.mu_k));
  } catch (const std::exception&) {
    // No harmonic motion: the offset is the best guess of the plate's travel.
  }
  Eigen::AlignedBox3f box;
  for (const double x : {-amplitude, amplitude}) {
    pose.plate_x = x;
    for (const RigPart& part : model_.parts) {
      const PlacedPart placed = place_part(model_, part, pose, 0.0);
      const auto& positions = model_.meshes[placed.mesh].positions;
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const Eigen::Vector3f v = placed.pose * positions[i];
        box.extend(v);
        // About one point in 16 frames the camera (every point of a small mesh).
        if (positions.size() < 64 || i % 16 == 0) model_.outline.push_back(v);
      }
    }
  }
  model_.bounds = box;
  model_.shadow = ShadowBounds{box.center(), box.diagonal().norm() / 2.0f};
  // The board: the rig's footprint and a margin for its shadows, in whole 4 cm tiles.
  const float tile = 0.04f;
  const auto snap_down = [tile](float v) { return std::floor(v / tile) * tile; };
  const auto snap_up = [tile](float v) { return std::ceil(v / tile) * tile; };
  model_.ground = add_mesh(make_board(
      Eigen::Vector2f(snap_down(box.min().x() - 0.10f), snap_down(box.min().y() - 0.06f)),
      Eigen::Vector2f(snap_up(box.max().x() + 0.10f), snap_up(box.max().y() + 0.10f)),
      model_.ground_z, tile));
}

RigModel ModelBuilder::build() {
  add_shafts();
  add_static();
  add_plate();
  add_rollers_and_axles();
  add_gears();
  finish_bounds();
  for (const RigPart& part : model_.parts)
    if (part.body != RigPart::Body::kWorld)
      model_.stats.moving_triangles += model_.meshes[part.mesh].triangle_count();
  if (meshes_ != nullptr) model_.stats.meshes_read = meshes_->files_read();
  return std::move(model_);
}

// The nearest blur level to a sweep.
std::size_t blur_level(double sweep) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < kBlurSweeps.size(); ++i)
    if (std::fabs(kBlurSweeps[i] - sweep) < std::fabs(kBlurSweeps[best] - sweep)) best = i;
  return best;
}

// A camera looking along -`direction` that frames `box` inside the part of the picture the
// overlay leaves free (x from 3 % to 97 %, y from `top` to `bottom`, as fractions of the
// height from the top), as close as that allows: the target is moved down the picture so that
// the box's centre lands in the middle of that region.
Camera fit_camera(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& direction,
                  float fov_y, int width, int height, float top, float bottom) {
  Camera c;
  c.fov_y_degrees = fov_y;
  Eigen::AlignedBox3f box;
  for (const auto& p : points) box.extend(p);
  const Eigen::Vector3f centre = box.center();
  // The picture's up, in the world: the camera's up vector made orthogonal to the view.
  const Eigen::Vector3f up = (c.up - c.up.dot(direction) * direction).normalized();
  const float tan_half = std::tan(fov_y * static_cast<float>(kPi) / 360.0f);
  // The region's middle, in normalised device y (1 at the top).
  const float region_y = 1.0f - (top + bottom);
  const auto place = [&](float distance) {
    c.target = centre - up * (region_y * tan_half * distance);
    c.position = c.target + direction * distance;
  };
  const auto fits = [&](float distance) {
    place(distance);
    for (const auto& point : points) {
      const auto p = project_to_pixel(c, width, height, point);
      if (!p || p->x() < 0.03f * static_cast<float>(width) ||
          p->x() > 0.97f * static_cast<float>(width) || p->y() < top * static_cast<float>(height) ||
          p->y() > bottom * static_cast<float>(height))
        return false;
    }
    return true;
  };
  float lo = 0.01f, hi = 0.05f;
  while (!fits(hi) && hi < 50.0f) hi *= 2.0f;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (fits(mid) ? hi : lo) = mid;
  }
  place(hi);
  return c;
}

}  // namespace

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

bool scene_uses_parts(const Scene& scene) {
  return scene.frame.has_value() || scene.drive.has_value() || !scene.plate.blocks.empty();
}

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

RigPose rest_pose(const Scene& scene) {
  RigPose pose;
  pose.plate_x = scene.plate.offset;
  pose.plate_z = plate_mass(scene).h_c;
  const std::size_t shafts = scene.drive ? drive_layout(scene).shafts.size() : 2;
  pose.shaft_angles.assign(shafts, 0.0);
  pose.shaft_speeds.assign(shafts, 0.0);
  return pose;
}

RigPose interpolate(const RigPose& a, const RigPose& b, double f) {
  const auto mix = [f](double x, double y) { return x + (y - x) * f; };
  RigPose out;
  out.plate_x = mix(a.plate_x, b.plate_x);
  out.plate_y = mix(a.plate_y, b.plate_y);
  out.plate_z = mix(a.plate_z, b.plate_z);
  out.pitch = mix(a.pitch, b.pitch);
  out.yaw = mix(a.yaw, b.yaw);
  const std::size_t n = std::min(a.shaft_angles.size(), b.shaft_angles.size());
  out.shaft_angles.resize(n);
  out.shaft_speeds.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.shaft_angles[i] = mix(a.shaft_angles[i], b.shaft_angles[i]);
    out.shaft_speeds[i] = mix(a.shaft_speeds[i], b.shaft_speeds[i]);
  }
  return out;
}

Eigen::Affine3f plate_transform(const RigPose& pose) {
  return translation(Eigen::Vector3f(static_cast<float>(pose.plate_x),
                                     static_cast<float>(pose.plate_y),
                                     static_cast<float>(pose.plate_z))) *
         about_z(pose.yaw) * about_y(pose.pitch);
}

PlacedPart place_part(const RigModel& model, const RigPart& part, const RigPose& pose,
                      double exposure) {
  PlacedPart placed{part.mesh, part.local};
  switch (part.body) {
    case RigPart::Body::kWorld:
      break;
    case RigPart::Body::kPlate:
      placed.pose = plate_transform(pose) * part.local;
      break;
    case RigPart::Body::kShaft: {
      const auto s = static_cast<std::size_t>(part.shaft);
      const RigShaft& shaft = model.shafts.at(s);
      const double angle = s < pose.shaft_angles.size() ? pose.shaft_angles[s] : 0.0;
      const double speed = s < pose.shaft_speeds.size() ? pose.shaft_speeds[s] : 0.0;
      placed.pose = translation(Eigen::Vector3f(static_cast<float>(shaft.x), 0.0f,
                                                static_cast<float>(shaft.z))) *
                    about_y(angle + part.phase) * part.local;
      if (!part.blur_variants.empty())
        placed.mesh = part.blur_variants[blur_level(std::fabs(speed) * exposure)];
      break;
    }
  }
  return placed;
}

std::size_t RigModel::triangles(const RigPose& pose, double exposure) const {
  std::size_t n = meshes[ground].triangle_count();
  for (const RigPart& part : parts)
    n += meshes[place_part(*this, part, pose, exposure).mesh].triangle_count();
  return n;
}

RigModel build_rig_model(const Scene& scene, const assets::PartCatalog* catalog,
                         assets::MeshLibrary* meshes) {
  return ModelBuilder(scene, catalog, meshes).build();
}

Camera rig_camera(const RigModel& model, const VideoDesc& video) {
  Camera c;
  if (video.placed) {
    c.position = vec(video.placed->position);
    c.target = vec(video.placed->target);
    c.fov_y_degrees = static_cast<float>(video.placed->fov * 180.0 / kPi);
  } else if (video.camera == "sensor") {
    // The sensor and the magnet under it, with the plate's end and the board in view.
    const Eigen::Vector3f centre = 0.5f * (model.sensor + model.magnet);
    const Eigen::AlignedBox3f box(centre - Eigen::Vector3f(0.028f, 0.016f, 0.012f),
                                  centre + Eigen::Vector3f(0.028f, 0.016f, 0.012f));
    std::vector<Eigen::Vector3f> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back(box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)));
    c = fit_camera(corners, Eigen::Vector3f(0.30f, -1.0f, 0.45f).normalized(), 30.0f, video.width,
                   video.height, 0.16f, 0.70f);
  } else if (video.camera == "top") {
    c = fit_camera(model.outline, Eigen::Vector3f(0.0f, -0.30f, 1.0f).normalized(), 32.0f,
                   video.width, video.height, 0.08f, 0.70f);
  } else {
    c = fit_camera(model.outline, Eigen::Vector3f(0.30f, -1.0f, 0.75f).normalized(), 30.0f,
                   video.width, video.height, 0.08f, 0.70f);
  }
  const float distance = (c.position - c.target).norm();
  c.near_plane = std::max(0.005f, 0.05f * distance);
  c.far_plane = 40.0f * distance + 2.0f;
  return c;
}

Camera orbit_camera(const Camera& camera, double radians) {
  Camera c = camera;
  if (radians != 0.0)
    c.position = translation(c.target) * about_z(radians) * translation(-c.target) * c.position;
  return c;
}

DirectionalLight rig_light() {
  DirectionalLight light;
  light.direction = Eigen::Vector3f(-0.45f, 0.55f, -0.75f);
  light.intensity = 0.80f;
  light.ambient = 0.42f;
  return light;
}

RigView::RigView(Renderer& renderer, RigModel model)
    : renderer_(renderer), model_(std::move(model)) {
  for (const MeshData& mesh : model_.meshes) ids_.push_back(renderer_.upload(mesh));
  renderer_.set_shadow_bounds(model_.shadow);
}

void RigView::draw(const RigPose& pose, double exposure) const {
  for (const RigPart& part : model_.parts) {
    const PlacedPart placed = place_part(model_, part, pose, exposure);
    renderer_.draw(ids_[placed.mesh], placed.pose, part.casts_shadow);
  }
  // The ground last: where the rig covers it, its fragments fail the depth test before they are
  // shaded.
  renderer_.draw(ids_[model_.ground], Eigen::Affine3f::Identity(), false);
}

}  // namespace fl::render
