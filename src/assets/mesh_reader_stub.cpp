// read_part_mesh in a build without mesh import (FRICTIONLAB_WITH_ASSETS=OFF).
#include <string>

#include "assets/mesh_library.hpp"

namespace fl::assets {

PartMesh read_part_mesh(const std::string& file) {
  throw_missing("loading the mesh " + file, "mesh import (assimp)",
                "apt-get install libassimp-dev, then configure with -DFRICTIONLAB_WITH_ASSETS=ON");
}

}  // namespace fl::assets
