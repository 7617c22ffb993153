#include "cli/scene_options.hpp"

#include <memory>
#include <optional>

#include "cli/option_quantity.hpp"
#include "io/paper_table_yaml.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::cli {

void add_scene_options(CLI::App& command, SceneOptions& options) {
  command.add_option("scene", options.file, "Scene file (scenes/*.yaml)")->required();
  command.add_option("--set", options.overrides,
                     "Override a scene key, e.g. --set plate.thickness=5mm (repeatable)");
  command.add_option("--duration", options.duration, "Simulated time, e.g. 20s (world.duration)");
}

Scene load_scene_with_options(const SceneOptions& options, const GlobalOptions& global) {
  std::vector<SceneOverride> overrides;
  for (const std::string& text : options.overrides) overrides.push_back(parse_override(text));
  if (!options.duration.empty()) {
    option_quantity(options.duration, Dimension::kTime, "--duration");  // checks the unit
    overrides.push_back({"world.duration", options.duration});
  }
  const SceneSources sources = scene_sources(global);
  return load_scene_file(options.file, overrides, sources.paper, sources.parts);
}

SceneSources scene_sources(const GlobalOptions& global) {
  const std::string asset_dir = resolve_asset_dir(global.asset_dir);
  auto table = std::make_shared<std::optional<PaperTable>>();
  auto catalog = std::make_shared<std::optional<assets::PartCatalog>>();
  SceneSources sources;
  sources.paper = [table, asset_dir]() -> const PaperTable& {
    if (!*table) *table = load_paper_table(paper_table_path(asset_dir));
    return **table;
  };
  sources.parts = [catalog, asset_dir]() -> const assets::PartCatalog& {
    if (!*catalog) *catalog = assets::load_part_catalog(assets::part_catalog_path(asset_dir));
    return **catalog;
  };
  return sources;
}

}  // namespace fl::cli
