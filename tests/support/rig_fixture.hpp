// The paper's rig as the render tests and the render benchmarks use it: its scene
// (scenes/paper-rig.yaml), the paper's table and the LEGO part index, each loaded once, and the
// rig model built from them. Folders: FRICTIONLAB_TEST_ASSET_DIR and FRICTIONLAB_TEST_SOURCE_DIR
// (set for every test by fl_add_gtest, and for the benchmarks that include this file).
#pragma once

#include <string>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"
#include "io/paper_table_yaml.hpp"
#include "render/rig_model.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::test {

inline const assets::PartCatalog& part_catalog() {
  static const assets::PartCatalog catalog =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return catalog;
}

inline const PaperTable& paper_table() {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  return table;
}

// A scene of scenes/ by file name, e.g. "paper-rig.yaml".
inline Scene scene_file(const std::string& name) {
  return load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/" + name, {},
      []() -> const PaperTable& { return paper_table(); },
      []() -> const assets::PartCatalog& { return part_catalog(); });
}

inline const Scene& paper_rig() {
  static const Scene scene = scene_file("paper-rig.yaml");
  return scene;
}

// The paper's rig's model, its meshes read through a library of its own.
inline render::RigModel paper_rig_model() {
  assets::MeshLibrary meshes;
  return render::build_rig_model(compile_rig(paper_rig()), &part_catalog(), &meshes);
}

}  // namespace fl::test
