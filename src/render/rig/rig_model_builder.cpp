// Builds the rig model from the compiled rig (rig_model.hpp): its drive layout for the shafts and
// gears, its plate's mass properties for where the slab lies about the centre of mass, and its
// initial amplitude for the plate's travel.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "core/unequal_radii.hpp"
#include "render/rig/lego_merge.hpp"
#include "render/rig/rig_geometry.hpp"
#include "render/rig/rig_meshes.hpp"
#include "render/rig/rig_model.hpp"
#include "scene/drive_layout.hpp"

namespace fl::render {
namespace {

using rig::about_x;
using rig::about_z;
using rig::degrees_to_radians;
using rig::kPi;
using rig::LegoPlacement;
using rig::translation;
using rig::vec;

Color rgb(const std::array<float, 3>& c) {
  return Color{c[0], c[1], c[2], 1.0f};
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
  ModelBuilder(const CompiledRig& rig, const assets::PartCatalog* catalog,
               assets::MeshLibrary* meshes, bool cut_away)
      : rig_(rig), catalog_(catalog), meshes_(meshes), cut_away_(cut_away) {}

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

  const CompiledRig& rig_;
  const assets::PartCatalog* catalog_;
  assets::MeshLibrary* meshes_;
  bool cut_away_ = false;  // leave out the frame's parts on the near side
  RigModel model_;
  const DriveLayout* layout_ = nullptr;
  MeshData static_extra_;  // the sensor's board, stands, the motor: merged with the frame
};

void ModelBuilder::add_shafts() {
  const double l = rig_.rollers.spacing;
  if (rig_.drive) {
    layout_ = &rig_.drive->layout;
    for (const ShaftPlacement& s : layout_->shafts) model_.shafts.push_back({s.role, s.x, s.z});
  } else {
    // In the rig's frame, turned with the line through the rollers' tops (rig.contact_tilt):
    // rollers of different radii have their tops level there and their axes at -a_0 and -a_1,
    // l cos(asin((a_1 - a_0) / l)) apart (physics/rig_world.cpp).
    const std::array<double, 2>& a = rig_.roller_radii;
    const double along = tangent_spacing(l, a[0], a[1]);
    model_.shafts.push_back({"roller 0", -0.5 * along, -a[0]});
    model_.shafts.push_back({"roller 1", 0.5 * along, -a[1]});
  }
}

void ModelBuilder::add_static() {
  // The frame's LEGO parts, merged into one mesh.
  std::vector<LegoPlacement> parts;
  const float near_edge = static_cast<float>(-0.5 * rig_.plate_desc.width) + 1e-4f;
  if (rig_.frame) {
    for (const FramePart& fp : rig_.frame->parts) {
      const assets::PartSpec& spec = need_part(catalog_, fp.part);
      LegoPlacement p;
      p.spec = &spec;
      p.mesh = load(spec);
      p.pose = translation(vec(fp.position)) * about_z(degrees_to_radians(fp.turn));
      p.color = rgb(fp.color);
      if (auto body = rig::body_box(spec)) p.body = rig::moved(*body, p.pose);
      if (cut_away_) {
        float far_y = -std::numeric_limits<float>::max();
        for (const auto& v : p.mesh->positions) far_y = std::max(far_y, (p.pose * v).y());
        if (far_y < near_edge) {
          ++model_.stats.cut_away_parts;
          continue;
        }
      }
      parts.push_back(std::move(p));
    }
  }
  // The ground: the frame's lowest face (the table it stands on), else below the lowest part.
  const double a = rig_.rollers.radius;
  float ground = static_cast<float>(-2.0 * a - 0.03);
  if (!parts.empty()) {
    ground = std::numeric_limits<float>::max();
    for (const LegoPlacement& p : parts) {
      for (const auto& v : p.mesh->positions) ground = std::min(ground, (p.pose * v).z());
    }
  } else if (layout_) {
    for (const GearPlacement& g : layout_->gears) {
      const double r = rig_.drive->parts.gear(g.teeth).pitch_radius + 0.001;
      ground = std::min(ground, static_cast<float>(model_.shafts[g.shaft].z - r - 0.01));
    }
  }
  model_.ground_z = ground;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].body)
      parts[i].bottom_covered = rig::bottom_covered(*parts[i].body, i, parts, ground);
  model_.stats.frame_parts = parts.size();
  rig::MergedParts frame = rig::merge_visible(parts, &model_.stats.frame_triangles_full,
                                              &model_.stats.frame_triangles_drawn);

  // Without a frame, the rollers' axles rest on two plain stands each.
  if (!rig_.frame) {
    for (int k = 0; k < 2; ++k) {
      const RigShaft& s = model_.shafts[static_cast<std::size_t>(k)];
      rig::add_axle_stands(static_extra_, s.x, s.z, rig_.rollers.length, ground);
    }
  }

  // The Hall sensor: the chip (centred on the sensor's position) under its board, held by an
  // arm from a post beside the plate's path.
  if (rig_.sensor) {
    model_.sensor = vec(rig_.sensor->position);
    rig::add_hall_sensor(static_extra_, model_.sensor, rig_.plate_desc.width, ground);
  }

  // The motor: a can on its shaft, beyond its gear.
  if (layout_) {
    const RigShaft& m = model_.shafts[static_cast<std::size_t>(layout_->motor)];
    double gear_y = 0.5 * rig_.rollers.length;
    for (const GearPlacement& g : layout_->gears)
      if (g.shaft == layout_->motor) gear_y = std::max(gear_y, g.y);
    rig::add_motor(static_extra_, m.x, m.z, gear_y, ground);
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
  const PlateDesc& p = rig_.plate_desc;
  const PlateMass& mass = rig_.plate;
  const float x_c = static_cast<float>(mass.x_c);
  const float bottom = static_cast<float>(-mass.h_c);
  const float top = bottom + static_cast<float>(p.thickness);
  MeshData plate =
      make_box(Eigen::Vector3f(static_cast<float>(p.length), static_cast<float>(p.width),
                               static_cast<float>(p.thickness)),
               material_color(p.material));
  for (auto& v : plate.positions) v += Eigen::Vector3f(-x_c, 0.0f, bottom + (top - bottom) / 2.0f);
  // The blocks on its top (their cavities face the plate: left out).
  std::vector<LegoPlacement> blocks;
  for (const PlateBlock& b : p.blocks) {
    const assets::PartSpec& spec = need_part(catalog_, b.part);
    LegoPlacement placed;
    placed.spec = &spec;
    placed.mesh = load(spec);
    placed.pose =
        translation(Eigen::Vector3f(static_cast<float>(b.x) - x_c, static_cast<float>(b.y), top)) *
        about_z(degrees_to_radians(b.turn));
    if (auto body = rig::body_box(spec)) placed.body = rig::moved(*body, placed.pose);
    placed.bottom_covered = true;
    blocks.push_back(std::move(placed));
  }
  std::size_t full = 0, drawn = 0;
  rig::MergedParts merged = rig::merge_visible(blocks, &full, &drawn);
  // The magnets: nickel-plated discs, magnetised along z.
  const Color nickel{0.80f, 0.80f, 0.83f, 1.0f};
  for (const MagnetDesc& m : rig_.magnets) {
    plate.append(
        rig::make_plain_cylinder(static_cast<float>(m.diameter / 2.0),
                                 static_cast<float>(m.thickness), 24, nickel),
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
  const RigPose rest = rest_pose(rig_);
  double best = std::numeric_limits<double>::infinity();
  for (const MagnetDesc& m : rig_.magnets) {
    const Eigen::Vector3f at =
        plate_transform(rest) * Eigen::Vector3f(static_cast<float>(m.x) - x_c, 0.0f,
                                                top + static_cast<float>(m.height + m.thickness));
    const double d = (at - model_.sensor).norm();
    if (d < best) {
      best = d;
      model_.magnet = at;
    }
  }
  if (rig_.magnets.empty()) model_.magnet = model_.sensor;
}

void ModelBuilder::add_rollers_and_axles() {
  const float length = static_cast<float>(rig_.rollers.length);
  // The rollers, in every blur level; each its own size when the two differ.
  std::array<std::vector<std::size_t>, 2> variants;
  for (std::size_t k = 0; k < 2; ++k) {
    if (k == 1 && rig_.roller_radii[1] == rig_.roller_radii[0]) {
      variants[1] = variants[0];
      break;
    }
    const float a = static_cast<float>(rig_.roller_radii[k]);
    for (const double sweep : kBlurSweeps)
      variants[k].push_back(add_mesh(rig::make_roller(a, length, sweep)));
  }
  for (int k = 0; k < 2; ++k) {
    const std::vector<std::size_t>& own = variants[static_cast<std::size_t>(k)];
    RigPart part = make_part(own[0], RigPart::Body::kShaft, k);
    part.blur_variants = own;
    // The second roller's mark starts on the other side, so the two never look alike.
    part.phase = k == 0 ? 0.0 : kPi;
    model_.parts.push_back(part);
  }
  // An axle through each shaft, across its gears (and the frame, for the rollers).
  const assets::PartSpec* axle =
      catalog_ != nullptr && rig_uses_parts(rig_) ? catalog_->find("axle-12") : nullptr;
  std::size_t axle_mesh = 0;
  float axle_length = 1.0f;
  if (axle != nullptr && axle->axle) {
    axle_mesh = add_mesh(rig::lego_mesh_data(*load(*axle), Color{0.10f, 0.10f, 0.11f, 1.0f}));
    axle_length = static_cast<float>(axle->axle->length);
  } else {
    const Color dark{0.12f, 0.12f, 0.13f, 1.0f};
    axle_mesh = add_mesh(rig::make_plain_cylinder(0.0024f, 1.0f, 12, dark));
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
    const std::size_t sharp = add_mesh(rig::lego_mesh_data(*mesh, Color{0, 0, 0, 0}));
    const std::size_t blur = add_mesh(rig::make_gear_blur(spec, rig::average_color(*mesh)));
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
  RigPose pose = rest_pose(rig_);
  // The harmonic amplitude (the offset when there is no harmonic motion).
  const double amplitude = std::max(std::fabs(rig_.plate_desc.offset), rig_.amplitude_initial);
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
  model_.ground = add_mesh(rig::make_board(
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

}  // namespace

bool rig_uses_parts(const CompiledRig& rig) {
  return rig.frame.has_value() || rig.drive.has_value() || !rig.plate_desc.blocks.empty();
}

RigModel build_rig_model(const CompiledRig& rig, const assets::PartCatalog* catalog,
                         assets::MeshLibrary* meshes, bool cut_away_near_side) {
  RigModel model = ModelBuilder(rig, catalog, meshes, cut_away_near_side).build();
  // A tilted rig drawn tilted: turned about y by -tilt, so that +x rises by tilt (the line
  // through the rollers' tops, which rollers of different radii tilt as well).
  model.tilt = Eigen::Affine3f(
      Eigen::AngleAxisf(-static_cast<float>(rig.contact_tilt), Eigen::Vector3f::UnitY()));
  return model;
}

}  // namespace fl::render
