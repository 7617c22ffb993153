// The paper's rig as the render tests and the render benchmarks use it: its scene
// (scenes/paper-rig.yaml, through scene_fixture.hpp), loaded once, and the rig model built from it.
// Folders: FRICTIONLAB_TEST_ASSET_DIR and FRICTIONLAB_TEST_SOURCE_DIR (set for every test by
// fl_add_gtest, and for the benchmarks that include this file).
#pragma once

#include <string>

#include "assets/mesh_library.hpp"
#include "render/rig/rig_model.hpp"
#include "scene_fixture.hpp"

namespace fl::test {

inline const Scene& paper_rig() {
  static const Scene scene = scene_file("paper-rig.yaml");
  return scene;
}

// The paper's rig's model, its meshes read through a library of its own; `cut_away_near_side` as
// the front camera's videos draw it (render/rig/rig_model.hpp).
inline render::RigModel paper_rig_model(bool cut_away_near_side = false) {
  assets::MeshLibrary meshes;
  return render::build_rig_model(compile_rig(paper_rig()), &part_catalog(), &meshes,
                                 cut_away_near_side);
}

}  // namespace fl::test
