// read_part_mesh in a build without mesh import (FRICTIONLAB_WITH_ASSETS=OFF).
#include <string>

#include "assets/mesh_library.hpp"

namespace fl::assets {

PartMesh read_part_mesh(const std::string& file) {
  throw MissingComponent("loading the mesh " + file +
                         " needs mesh import (assimp), which this build of frictionlab does not "
                         "have (apt-get install libassimp-dev, then configure with "
                         "-DFRICTIONLAB_WITH_ASSETS=ON)");
}

}  // namespace fl::assets
