// The paper's rig for the rig-renderer tests: its scene (scenes/paper-rig.yaml) and part index,
// loaded once.
#pragma once

#include <optional>
#include <string>

#include "assets/part_catalog.hpp"
#include "io/paper_table_yaml.hpp"
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

}  // namespace fl::test
