// The repository's scenes as the tests load them: the paper's table and the LEGO part index each
// read once, a scene of scenes/ by file name with --set style overrides. Folders:
// FRICTIONLAB_TEST_ASSET_DIR and FRICTIONLAB_TEST_SOURCE_DIR (set for every test by fl_add_gtest,
// and for the benchmarks that include this file).
#pragma once

#include <span>
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

// A scene of scenes/ by file name, e.g. "minimal.yaml", with overrides applied.
inline Scene scene_file(const std::string& name, std::span<const SceneOverride> overrides = {}) {
  return load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/" + name, overrides,
      []() -> const PaperTable& { return paper_table(); },
      []() -> const assets::PartCatalog& { return part_catalog(); });
}

// The minimal scene without its sensor, overrides applied: for tests that compare the trajectory.
inline Scene minimal_without_sensor(std::span<const SceneOverride> overrides = {}) {
  Scene s = scene_file("minimal.yaml", overrides);
  s.sensor.reset();
  return s;
}

}  // namespace fl::test
