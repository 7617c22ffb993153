#include "cli/scene_options.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "lab/request/lab_data.hpp"

namespace fl::cli {

void add_scene_options(CLI::App& command, SceneOptions& options) {
  command.add_option("scene", options.file, "Scene file (scenes/*.yaml)")->required();
  command.add_option("--set", options.overrides,
                     "Override a scene key, e.g. --set plate.thickness=5mm (repeatable)");
  command.add_option("--duration", options.duration, "Simulated time, e.g. 20s (world.duration)");
}

SceneSource scene_source_of(const SceneOptions& options, const GlobalOptions& global) {
  SceneSource source;
  source.file = options.file;
  source.asset_dir = global.asset_dir;
  return source;
}

Scene load_scene_with_options(const SceneOptions& options, const GlobalOptions& global) {
  FieldChecks checks;
  SceneSource source = scene_source_of(options, global);
  source.overrides = read_overrides(options.overrides, checks);
  std::optional<QuantityInput> duration;
  if (!options.duration.empty()) duration = options.duration;
  const std::vector<SceneOverride> length = run_length_overrides(duration, std::nullopt, checks);
  source.overrides.insert(source.overrides.end(), length.begin(), length.end());
  checks.throw_if_any();
  return *load_scene_source(std::move(source)).scene;
}

SceneInputs scene_sources(const GlobalOptions& global) {
  return scene_inputs(asset_dir(global.asset_dir));
}

}  // namespace fl::cli
