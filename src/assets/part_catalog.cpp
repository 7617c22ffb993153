#include "assets/part_catalog.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "io/suggest.hpp"
#include "io/yaml_node.hpp"

namespace fl::assets {
namespace {

// Shapes may touch the part's bounds; the index's numbers are rounded to 0.1 um.
constexpr double kSlack = 1e-7;  // m

constexpr std::array<std::pair<std::string_view, PartKind>, 5> kKinds{{
    {"brick", PartKind::kBrick},
    {"plate", PartKind::kPlate},
    {"technic-brick", PartKind::kTechnicBrick},
    {"axle", PartKind::kAxle},
    {"gear", PartKind::kGear},
}};

PartKind read_kind(const YamlNode& node) {
  const std::string text = node.text();
  std::vector<std::string_view> names;
  for (const auto& [name, kind] : kKinds) {
    if (name == text) return kind;
    names.push_back(name);
  }
  std::string message = "unknown kind \"" + text + "\"";
  const std::string suggestion = closest_match(text, names);
  if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
  message += " (the kinds are brick, plate, technic-brick, axle, gear)";
  node.fail(message);
}

Axis read_axis(const YamlNode& node) {
  const std::string text = node.text();
  if (text == "x") return Axis::kX;
  if (text == "y") return Axis::kY;
  if (text == "z") return Axis::kZ;
  node.fail("expected an axis x, y or z, found \"" + text + "\"");
}

int axis_index(Axis axis) {
  return axis == Axis::kX ? 0 : axis == Axis::kY ? 1 : 2;
}

double positive(const YamlNode& node, Dimension dimension) {
  const double value = node.quantity(dimension);
  if (!(value > 0.0) || !std::isfinite(value)) node.fail("expected a positive value");
  return value;
}

Vec3 read_vec3(const YamlNode& node, Dimension dimension) {
  if (node.size() != 3)
    node.fail("expected three values [x, y, z], found " + std::to_string(node.size()));
  return {node[0].quantity(dimension), node[1].quantity(dimension), node[2].quantity(dimension)};
}

Vec3 read_positive_vec3(const YamlNode& node, Dimension dimension) {
  const Vec3 v = read_vec3(node, dimension);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(v[i] > 0.0)) node[i].fail("expected a positive value");
  }
  return v;
}

std::array<float, 3> read_color(const YamlNode& node) {
  const std::string text = node.text();
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::array<float, 3> color{};
  bool ok = text.size() == 7 && text[0] == '#';
  for (std::size_t i = 0; ok && i < 3; ++i) {
    const int high = hex(text[1 + 2 * i]);
    const int low = hex(text[2 + 2 * i]);
    ok = high >= 0 && low >= 0;
    color[i] = static_cast<float>(high * 16 + low) / 255.0f;
  }
  if (!ok) node.fail("expected an sRGB colour \"#RRGGBB\", found \"" + text + "\"");
  return color;
}

// The mesh file: a plain relative path below the index's folder.
std::string read_file(const YamlNode& node, const std::string& mesh_dir) {
  const std::string text = node.text();
  const std::filesystem::path path(text);
  if (text.empty() || path.is_absolute())
    node.fail("expected a file name relative to the index's folder, found \"" + text + "\"");
  for (const auto& part : path) {
    if (part == "..") node.fail("the mesh file must lie in the index's folder or below it");
  }
  if (mesh_dir.empty()) return path.lexically_normal().string();
  return (std::filesystem::path(mesh_dir) / path).lexically_normal().string();
}

void check_inside(const YamlNode& node, const Aabb& bounds, const Vec3& low, const Vec3& high) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (low[i] < bounds.min[i] - kSlack || high[i] > bounds.max[i] + kSlack)
      node.fail("the shape reaches outside the part's bounds along " +
                std::string(1, static_cast<char>('x' + i)) + " (" + std::to_string(low[i]) +
                " .. " + std::to_string(high[i]) + " m against " + std::to_string(bounds.min[i]) +
                " .. " + std::to_string(bounds.max[i]) + " m)");
  }
}

Aabb read_bounds(const YamlNode& node) {
  node.allow_keys({"min", "max"});
  Aabb box{read_vec3(node.at("min"), Dimension::kLength),
           read_vec3(node.at("max"), Dimension::kLength)};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(box.min[i] < box.max[i])) node.fail("expected min < max along every axis");
  }
  return box;
}

void read_collision(const YamlNode& node, PartSpec& part) {
  node.allow_keys({"boxes", "cylinders"});
  if (auto boxes = node.find("boxes")) {
    for (std::size_t i = 0; i < boxes->size(); ++i) {
      const YamlNode entry = (*boxes)[i];
      entry.allow_keys({"center", "size"});
      CollisionBox box{read_vec3(entry.at("center"), Dimension::kLength),
                       read_positive_vec3(entry.at("size"), Dimension::kLength)};
      Vec3 low{}, high{};
      for (std::size_t k = 0; k < 3; ++k) {
        low[k] = box.center[k] - box.size[k] / 2;
        high[k] = box.center[k] + box.size[k] / 2;
      }
      check_inside(entry, part.bounds, low, high);
      part.boxes.push_back(box);
    }
  }
  if (auto cylinders = node.find("cylinders")) {
    for (std::size_t i = 0; i < cylinders->size(); ++i) {
      const YamlNode entry = (*cylinders)[i];
      entry.allow_keys({"center", "axis", "radius", "length"});
      CollisionCylinder cylinder;
      cylinder.center = read_vec3(entry.at("center"), Dimension::kLength);
      cylinder.axis = read_axis(entry.at("axis"));
      cylinder.radius = positive(entry.at("radius"), Dimension::kLength);
      cylinder.length = positive(entry.at("length"), Dimension::kLength);
      Vec3 low{}, high{};
      for (int k = 0; k < 3; ++k) {
        const double half = k == axis_index(cylinder.axis) ? cylinder.length / 2 : cylinder.radius;
        low[static_cast<std::size_t>(k)] = cylinder.center[static_cast<std::size_t>(k)] - half;
        high[static_cast<std::size_t>(k)] = cylinder.center[static_cast<std::size_t>(k)] + half;
      }
      check_inside(entry, part.bounds, low, high);
      part.cylinders.push_back(cylinder);
    }
  }
  if (part.boxes.empty() && part.cylinders.empty())
    node.fail("expected at least one collision shape (boxes or cylinders)");
}

GearData read_gear(const YamlNode& node) {
  node.allow_keys(
      {"teeth", "module", "pitch_radius", "outer_radius", "root_radius", "width", "hub_width"});
  GearData gear;
  const std::int64_t teeth = node.at("teeth").integer();
  if (teeth < 4 || teeth > 1000) node.at("teeth").fail("expected 4 to 1000 teeth");
  gear.teeth = static_cast<int>(teeth);
  gear.module = positive(node.at("module"), Dimension::kLength);
  gear.pitch_radius = positive(node.at("pitch_radius"), Dimension::kLength);
  gear.outer_radius = positive(node.at("outer_radius"), Dimension::kLength);
  gear.root_radius = positive(node.at("root_radius"), Dimension::kLength);
  gear.width = positive(node.at("width"), Dimension::kLength);
  gear.hub_width = positive(node.at("hub_width"), Dimension::kLength);
  const double pitch = gear.teeth * gear.module / 2;
  if (std::fabs(gear.pitch_radius - pitch) > 1e-6 * pitch)
    node.at("pitch_radius")
        .fail("expected teeth x module / 2 = " + std::to_string(pitch) + " m, found " +
              std::to_string(gear.pitch_radius) + " m");
  if (!(gear.root_radius < gear.pitch_radius && gear.pitch_radius < gear.outer_radius))
    node.fail("expected root_radius < pitch_radius < outer_radius");
  return gear;
}

PartSpec read_part(const YamlNode& node, const std::string& mesh_dir) {
  node.allow_keys({"name", "file", "kind", "description", "color", "triangles", "bounds", "volume",
                   "mass", "center_of_mass", "inertia", "studs", "plates", "holes", "axle", "gear",
                   "collision"});
  PartSpec part;
  part.name = node.at("name").text();
  if (part.name.empty()) node.at("name").fail("expected a part name");
  part.file = read_file(node.at("file"), mesh_dir);
  part.kind = read_kind(node.at("kind"));
  if (auto description = node.find("description")) part.description = description->text();
  if (auto color = node.find("color")) part.color = read_color(*color);
  const std::int64_t triangles = node.at("triangles").integer();
  if (triangles < 1 || triangles > 10'000'000)
    node.at("triangles").fail("expected 1 to 10000000 triangles");
  part.triangles = static_cast<int>(triangles);
  part.bounds = read_bounds(node.at("bounds"));
  part.volume = node.at("volume").number();
  if (!(part.volume > 0.0)) node.at("volume").fail("expected a positive volume in m^3");
  part.mass = positive(node.at("mass"), Dimension::kMass);
  part.center_of_mass = read_vec3(node.at("center_of_mass"), Dimension::kLength);
  check_inside(node.at("center_of_mass"), part.bounds, part.center_of_mass, part.center_of_mass);
  const YamlNode inertia = node.at("inertia");
  if (inertia.size() != 3) inertia.fail("expected three principal moments [Ixx, Iyy, Izz]");
  for (std::size_t i = 0; i < 3; ++i) {
    part.inertia[i] = inertia[i].number();
    if (!(part.inertia[i] > 0.0)) inertia[i].fail("expected a positive moment in kg m^2");
  }

  const bool stacks = part.kind == PartKind::kBrick || part.kind == PartKind::kPlate ||
                      part.kind == PartKind::kTechnicBrick;
  const std::string kind_name(part_kind_name(part.kind));
  if (stacks) {
    const YamlNode studs = node.at("studs");
    if (studs.size() != 2) studs.fail("expected [along x, along y]");
    for (std::size_t i = 0; i < 2; ++i) {
      const std::int64_t n = studs[i].integer();
      if (n < 1 || n > 64) studs[i].fail("expected 1 to 64 studs");
      part.studs[i] = static_cast<int>(n);
    }
    const std::int64_t plates = node.at("plates").integer();
    if (plates < 1 || plates > 64) node.at("plates").fail("expected 1 to 64 plates");
    part.plates = static_cast<int>(plates);
  } else {
    for (const char* key : {"studs", "plates"}) {
      if (node.has(key)) node.at(key).fail("a " + kind_name + " has no " + key);
    }
  }
  if (auto holes = node.find("holes")) {
    if (part.kind != PartKind::kTechnicBrick)
      holes->fail("only a technic-brick has holes, not a " + kind_name);
    for (std::size_t i = 0; i < holes->size(); ++i) {
      const YamlNode entry = (*holes)[i];
      entry.allow_keys({"center", "axis", "diameter"});
      Hole hole;
      hole.center = read_vec3(entry.at("center"), Dimension::kLength);
      hole.axis = read_axis(entry.at("axis"));
      hole.diameter = positive(entry.at("diameter"), Dimension::kLength);
      check_inside(entry.at("center"), part.bounds, hole.center, hole.center);
      part.holes.push_back(hole);
    }
  }
  if (part.kind == PartKind::kTechnicBrick && part.holes.empty())
    node.fail("a technic-brick needs its holes");
  if (auto axle = node.find("axle")) {
    if (part.kind != PartKind::kAxle) axle->fail("only an axle has axle data, not a " + kind_name);
    axle->allow_keys({"length", "cross", "arm"});
    part.axle = AxleData{positive(axle->at("length"), Dimension::kLength),
                         positive(axle->at("cross"), Dimension::kLength),
                         positive(axle->at("arm"), Dimension::kLength)};
    if (!(part.axle->arm < part.axle->cross)) axle->fail("expected arm < cross");
  } else if (part.kind == PartKind::kAxle) {
    node.fail("an axle needs 'axle: {length, cross, arm}'");
  }
  if (auto gear = node.find("gear")) {
    if (part.kind != PartKind::kGear) gear->fail("only a gear has gear data, not a " + kind_name);
    part.gear = read_gear(*gear);
  } else if (part.kind == PartKind::kGear) {
    node.fail("a gear needs 'gear: {teeth, module, pitch_radius, ...}'");
  }
  read_collision(node.at("collision"), part);
  return part;
}

}  // namespace

std::string_view part_kind_name(PartKind kind) {
  for (const auto& [name, k] : kKinds) {
    if (k == kind) return name;
  }
  return "unknown";
}

PartCatalog::PartCatalog(std::string index_file, std::vector<PartSpec> parts)
    : index_file_(std::move(index_file)), parts_(std::move(parts)) {
  for (std::size_t i = 0; i < parts_.size(); ++i) by_name_.emplace(parts_[i].name, i);
}

const PartSpec* PartCatalog::find(std::string_view name) const {
  const auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : &parts_[it->second];
}

const PartSpec& PartCatalog::at(std::string_view name) const {
  if (const PartSpec* part = find(name)) return *part;
  std::vector<std::string_view> names;
  names.reserve(parts_.size());
  for (const PartSpec& part : parts_) names.push_back(part.name);
  std::string message = "unknown LEGO part '" + std::string(name) + "'";
  const std::string suggestion = closest_match(name, names);
  if (!suggestion.empty()) {
    message += "; did you mean '" + suggestion + "'?";
  } else {
    message += "; the parts are listed in " +
               (index_file_.empty() ? std::string("the catalogue") : index_file_);
  }
  throw UnknownPart(message);
}

namespace {

PartCatalog read_catalog(const YamlNode& root, const std::string& name,
                         const std::string& mesh_dir) {
  root.allow_keys({"format", "generator", "density", "parts"});
  if (root.at("format").integer() != 1)
    root.at("format").fail("this build reads format 1 of the parts index");
  if (auto generator = root.find("generator")) generator->integer();
  if (auto density = root.find("density")) positive(*density, Dimension::kDensity);
  const YamlNode list = root.at("parts");
  if (list.size() == 0) list.fail("expected at least one part");
  std::vector<PartSpec> parts;
  std::map<std::string, std::size_t, std::less<>> seen;
  for (std::size_t i = 0; i < list.size(); ++i) {
    PartSpec part = read_part(list[i], mesh_dir);
    if (!seen.emplace(part.name, i).second)
      list[i].at("name").fail("the part '" + part.name + "' is listed twice (first at parts[" +
                              std::to_string(seen[part.name]) + "])");
    parts.push_back(std::move(part));
  }
  return PartCatalog(name, std::move(parts));
}

}  // namespace

PartCatalog parse_part_catalog(std::string_view text, const std::string& name,
                               const std::string& mesh_dir) {
  return read_catalog(load_yaml_text(text, name), name, mesh_dir);
}

PartCatalog load_part_catalog(const std::string& index_file) {
  const YamlNode root = load_yaml_file(index_file);
  const std::string dir = std::filesystem::path(index_file).parent_path().string();
  return read_catalog(root, index_file, dir);
}

std::string part_catalog_path(const std::string& asset_dir) {
  return asset_dir + "/lego/parts.yaml";
}

}  // namespace fl::assets
