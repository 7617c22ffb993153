#include "cli/scene_options.hpp"

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

}  // namespace fl::cli
