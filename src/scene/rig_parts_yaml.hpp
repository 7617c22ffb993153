// The scene keys that name LEGO parts: the plate's blocks, the drive's gears and the frame. Each
// resolves its parts against the part index (sizes, masses, collision boxes), so the physics
// never opens the index or a mesh.
#pragma once

#include <functional>
#include <vector>

#include "assets/part_catalog.hpp"
#include "io/yaml_node.hpp"
#include "scene/scene.hpp"

namespace fl {

// The part index, fetched on first use; `where` locates the error when there is none.
using CatalogGetter = std::function<const assets::PartCatalog&(const YamlNode& where)>;

std::vector<PlateBlock> read_plate_blocks(const YamlNode& node, const CatalogGetter& catalog);
DriveDesc read_drive(const YamlNode& node, const CatalogGetter& catalog);
FrameDesc read_frame(const YamlNode& node, const CatalogGetter& catalog);

// A part's origin in the world for a placement on the stud grid (docs/lego-parts.md): a part of
// nx x ny studs whose first stud sits in cell (i, j), k plates up, turned by `turn` degrees.
Vec3 grid_position(const assets::PartSpec& part, const std::array<int, 3>& at, int turn,
                   const Vec3& origin);

}  // namespace fl
