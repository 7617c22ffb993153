// The paper's rig as geometry on the CPU, built once from the scene the physics uses (no GL, so
// it is testable anywhere): the LEGO frame (every static part merged into one mesh, with the
// faces no camera can see left out), the rollers (PVC tubes with a mark that smears into motion
// blur at speed), the gear train posed on its shafts, the plate with its blocks and magnets, the
// Hall sensor's board, and a ground. RigView (rig_view.hpp) uploads it and draws it at a RigPose.
//
// Coordinates are the scene's: x along the plate's motion, z up, metres.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"
#include "render/gl/renderer.hpp"
#include "render/mesh_data.hpp"
#include "render/rig/rig_pose.hpp"
#include "scene/compiled_rig.hpp"

namespace fl::render {

// One placement of a mesh: `local` in the frame of `body`.
struct RigPart {
  enum class Body { kWorld, kPlate, kShaft };
  std::size_t mesh = 0;  // index into RigModel::meshes
  Body body = Body::kWorld;
  int shaft = 0;       // Body::kShaft: which shaft
  double phase = 0.0;  // rad added to the shaft's angle (gears' teeth interleave)
  // Body::kShaft: the mesh drawn at each of kBlurSweeps (empty: `mesh` at every speed).
  std::vector<std::size_t> blur_variants;
  Eigen::Affine3f local = Eigen::Affine3f::Identity();
  bool casts_shadow = true;
};

struct RigShaft {
  std::string role;  // "roller 0", "idler 1", "motor", ...
  double x = 0.0;    // m, of its axis (along y)
  double z = 0.0;    // m
};

// Sweeps (rad turned during one exposure) the blurred variants of a turning part are made for;
// a frame picks the nearest. Index 0 is the still part.
inline constexpr std::array<double, 8> kBlurSweeps = {0.0,  0.26, 0.52, 0.87,
                                                      1.31, 2.09, 3.14, 6.28};

struct RigModelStats {
  std::size_t frame_parts = 0;            // LEGO parts of the frame
  std::size_t frame_triangles_full = 0;   // their meshes' triangles, all of them
  std::size_t frame_triangles_drawn = 0;  // after leaving out what no camera can see
  std::size_t moving_triangles = 0;       // plate, rollers, gears, axles (at rest)
  std::size_t meshes_read = 0;            // LEGO mesh files opened
  std::size_t cut_away_parts = 0;         // frame parts left out of a cutaway
};

struct RigModel {
  std::vector<MeshData> meshes;
  std::vector<RigPart> parts;
  std::vector<RigShaft> shafts;          // 0 and 1 are the rollers
  std::size_t ground = 0;                // the ground's mesh (drawn without casting shadows)
  float ground_z = 0.0f;                 // m
  Eigen::AlignedBox3f bounds;            // everything but the ground, over the plate's travel
  std::vector<Eigen::Vector3f> outline;  // points of everything but the ground (camera framing)
  ShadowBounds shadow;                   // fixed: the static parts' shadows never move
  Eigen::Vector3f sensor = Eigen::Vector3f::Zero();  // the Hall sensor (or where it would be)
  Eigen::Vector3f magnet = Eigen::Vector3f::Zero();  // the magnet nearest the sensor, at rest
  // The rig's frame in the world's: a rig tilted by world.tilt turned about y so that +x rises,
  // the ground (its table) with it; the identity for a level rig.
  Eigen::Affine3f tilt = Eigen::Affine3f::Identity();
  RigModelStats stats;

  // Triangles drawn in the camera pass at `pose` (with blur: proxies replace fast gears).
  std::size_t triangles(const RigPose& pose, double exposure) const;
};

// Builds the rig (rig_model_builder.cpp). LEGO meshes (frame parts, plate blocks, gears, axles)
// come from `meshes` through `catalog`; a scene that names no LEGO part needs neither (pass
// nullptr) and opens no file. Throws std::invalid_argument if a part is missing from the
// catalogue, and whatever MeshLibrary throws for a mesh file it cannot read.
//
// `cut_away_near_side`: the frame's parts wholly on the near side of the plate (y below the
// plate's near edge, where the front camera looks from) are left out, as in a cutaway drawing,
// so the rollers show; the model's stats count them in cut_away_parts.
RigModel build_rig_model(const CompiledRig& rig, const assets::PartCatalog* catalog,
                         assets::MeshLibrary* meshes, bool cut_away_near_side = false);

// Whether the scene names LEGO parts (a frame, blocks on the plate, a gear train).
bool rig_uses_parts(const CompiledRig& rig);

// For a camera that does not move (no orbit): leaves out of the static parts drawn without
// casting shadows (the frame; their shadows come from hidden casters) every triangle that
// faces away from `eye`, which the camera pass would only cull. Returns how many went.
std::size_t cull_back_faces(RigModel& model, const Eigen::Vector3f& eye);

// The world transform of a part at a pose, and the mesh drawn for it (the blurred variant when
// its shaft turns fast enough over `exposure`).
struct PlacedPart {
  std::size_t mesh = 0;
  Eigen::Affine3f pose = Eigen::Affine3f::Identity();
};
PlacedPart place_part(const RigModel& model, const RigPart& part, const RigPose& pose,
                      double exposure);

}  // namespace fl::render
