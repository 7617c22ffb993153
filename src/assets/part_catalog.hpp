// The LEGO parts' catalogue: assets/lego/parts.yaml, written by tools/generate-lego-parts beside
// the meshes. It holds what the physics needs of a part (size, mass, inertia, collision shapes,
// Technic holes, axle and gear data), so building a world never opens a mesh file: collision
// shapes come from here, never from the render mesh. Meshes are loaded by MeshLibrary
// (mesh_library.hpp) only when something is drawn. This target does not depend on assimp.
//
// Part frames (docs/lego-parts.md): z up. Bricks, plates and Technic bricks stand on z = 0,
// centred in x and y, their length along x. Axles lie along y and gears turn about y, both
// centred on the origin. Every length is in m, masses in kg, inertia in kg m^2.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fl::assets {

// LEGO's grid, m.
inline constexpr double kStudPitch = 0.008;      // stud to stud
inline constexpr double kBrickHeight = 0.0096;   // a brick's body, studs not included
inline constexpr double kPlateHeight = 0.0032;   // a plate's body; a brick is three plates
inline constexpr double kStudHeight = 0.0017;    // above the body
inline constexpr double kStudDiameter = 0.0048;  // also a Technic hole's and an axle's cross

using Vec3 = std::array<double, 3>;  // m, in the part's frame (same type as fl::Vec3)

enum class PartKind { kBrick, kPlate, kTechnicBrick, kAxle, kGear };
enum class Axis { kX, kY, kZ };

// "brick", "plate", "technic-brick", "axle", "gear" (as written in parts.yaml).
std::string_view part_kind_name(PartKind kind);

struct Aabb {
  Vec3 min{};  // m
  Vec3 max{};  // m
};

// An axis-aligned box of the part's collision compound.
struct CollisionBox {
  Vec3 center{};  // m
  Vec3 size{};    // m, full edge lengths
};

// A cylinder of the part's collision compound (gears: the toothed rim at the outer radius, and
// the hub).
struct CollisionCylinder {
  Vec3 center{};  // m
  Axis axis = Axis::kY;
  double radius = 0;  // m
  double length = 0;  // m, along the axis
};

// A Technic hole (an axle or a pin goes through it).
struct Hole {
  Vec3 center{};  // m, midway through the hole
  Axis axis = Axis::kY;
  double diameter = 0;  // m
};

struct AxleData {
  double length = 0;  // m, end to end
  double cross = 0;   // m, across the cross, tip to tip
  double arm = 0;     // m, thickness of the cross's arms
};

struct GearData {
  int teeth = 0;
  double module = 0;        // m (0.001 for Technic spur gears)
  double pitch_radius = 0;  // m, teeth x module / 2: meshing gears' radii add up to their spacing
  double outer_radius = 0;  // m, (teeth + 2) x module / 2
  double root_radius = 0;   // m, (teeth - 2.5) x module / 2
  double width = 0;         // m, of the teeth along the axis
  double hub_width = 0;     // m, of the hub along the axis
};

struct PartSpec {
  std::string name;         // "brick-2x4"
  std::string file;         // the mesh file, resolved against the index's folder
  std::string description;  // "Brick 2 x 4 (3001)"
  PartKind kind = PartKind::kBrick;
  std::array<float, 3> color{1, 1, 1};  // sRGB, 0..1: the part's default colour
  int triangles = 0;                    // in the mesh (the renderer's budget)
  Aabb bounds;                          // m, of the whole mesh (studs included)
  double volume = 0;                    // m^3, of the solid
  double mass = 0;                      // kg (ABS, 1050 kg/m^3)
  Vec3 center_of_mass{};                // m
  Vec3 inertia{};                       // kg m^2, principal, about the centre of mass, along x y z
  std::array<int, 2> studs{0, 0};       // bricks and plates: studs along x and y
  int plates = 0;                       // bricks and plates: height in plates (a brick is 3)
  std::vector<Hole> holes;              // Technic bricks
  std::optional<AxleData> axle;         // axles
  std::optional<GearData> gear;         // gears
  std::vector<CollisionBox> boxes;      // the collision compound: boxes ...
  std::vector<CollisionCylinder> cylinders;  // ... and cylinders; at least one shape in all
};

// A part name the catalogue does not have; what() suggests the closest one.
class UnknownPart : public std::out_of_range {
 public:
  using std::out_of_range::out_of_range;
};

class PartCatalog {
 public:
  PartCatalog() = default;
  PartCatalog(std::string index_file, std::vector<PartSpec> parts);

  const std::string& index_file() const { return index_file_; }
  const std::vector<PartSpec>& parts() const { return parts_; }
  std::size_t size() const { return parts_.size(); }

  // nullptr if there is no such part.
  const PartSpec* find(std::string_view name) const;
  // Throws UnknownPart: "unknown LEGO part 'brik-2x4'; did you mean 'brick-2x4'?". A scene
  // loader catches it and re-throws it located at the scene's key.
  const PartSpec& at(std::string_view name) const;

 private:
  std::string index_file_;
  std::vector<PartSpec> parts_;
  std::map<std::string, std::size_t, std::less<>> by_name_;
};

// Reads an index; mesh files are named relative to the index's folder and are not opened.
// Throws InputError located at file:line:column for anything malformed.
PartCatalog load_part_catalog(const std::string& index_file);

// The same from text; `name` stands in for the file in errors, `mesh_dir` resolves file names.
PartCatalog parse_part_catalog(std::string_view text, const std::string& name,
                               const std::string& mesh_dir);

// <asset_dir>/lego/parts.yaml
std::string part_catalog_path(const std::string& asset_dir);

}  // namespace fl::assets
