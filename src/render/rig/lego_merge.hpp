// LEGO parts merged into one mesh with the faces no camera can see left out (internal to the
// render library; the model builder merges the frame and the plate's blocks with it). The other
// half of hidden-face removal, cull_back_faces for a camera that stays put, is in rig_model.hpp.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"
#include "render/mesh_data.hpp"

namespace fl::render::rig {

// A LEGO mesh as MeshData, in `color` (or its own colours when color.a == 0).
MeshData lego_mesh_data(const assets::PartMesh& part, const Color& color);
// The mean of a LEGO mesh's vertex colours.
Color average_color(const assets::PartMesh& mesh);

// The body of a brick, plate or Technic brick (studs not included), in its own frame: the
// region its cavity and studs hide in. None for a part without plates (gears, axles).
std::optional<Eigen::AlignedBox3f> body_box(const assets::PartSpec& spec);
// A box moved by a pose that turns by multiples of 90 degrees about z (stays axis-aligned).
Eigen::AlignedBox3f moved(const Eigen::AlignedBox3f& box, const Eigen::Affine3f& pose);

// A part placed on the grid (frame parts, the plate's blocks), before merging.
struct LegoPlacement {
  const assets::PartSpec* spec = nullptr;
  std::shared_ptr<const assets::PartMesh> mesh;
  Eigen::Affine3f pose = Eigen::Affine3f::Identity();
  Color color{0, 0, 0, 0};                  // a = 0: the mesh's own colours
  std::optional<Eigen::AlignedBox3f> body;  // in the merged mesh's frame
  bool bottom_covered = false;
};

// Whether something covers the whole underside of `body`: the ground, or bodies whose tops lie
// in its bottom plane (checked on a 1 mm grid over its footprint). `self` is body's own index.
bool bottom_covered(const Eigen::AlignedBox3f& body, std::size_t self,
                    const std::vector<LegoPlacement>& parts, std::optional<float> ground_z);

// The parts merged, as drawn (`visible`) and as they cast shadows (`shadow`).
struct MergedParts {
  MeshData visible;
  MeshData shadow;
};

// Merges the parts into one mesh, leaving out the triangles no camera above the ground can see:
// those inside another part's body (studs under the brick above, a top face under a brick) and,
// for a part whose underside is covered, those of its cavity (inner walls, tubes, the underside
// of its top) and of its bottom rim; and the walls of Technic holes, whose inside shows the
// shadow caster instead (a dark box, like a hole's depth). Adds the triangles of the parts'
// meshes to *full and those kept to *drawn.
//
// The shadow caster of a part with a body is that body shrunk by 0.2 mm: it lies inside the
// drawn part (so the camera never sees it, but through a hole), casts the same shadow but for
// the studs' (a few pixels at 720p), and is 12 triangles instead of hundreds. A part without a
// body casts its own mesh.
MergedParts merge_visible(const std::vector<LegoPlacement>& parts, std::size_t* full,
                          std::size_t* drawn);

}  // namespace fl::render::rig
