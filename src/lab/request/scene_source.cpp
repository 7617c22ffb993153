#include "lab/request/scene_source.hpp"

#include <filesystem>
#include <utility>

#include "lab/request/lab_data.hpp"
#include "lab/request/plot_script.hpp"

namespace fl {

LoadedScene load_scene_source(SceneSource source) {
  const SceneInputs inputs = scene_inputs(asset_dir(source.asset_dir));
  Scene scene =
      source.file.empty()
          ? load_scene_text(source.text, source.name, source.overrides, inputs.paper, inputs.parts)
          : load_scene_file(source.file, source.overrides, inputs.paper, inputs.parts);
  return {std::make_shared<const Scene>(std::move(scene)), std::move(source)};
}

LoadedScene with_overrides(const LoadedScene& scene, const std::vector<SceneOverride>& more) {
  SceneSource source = scene.source;
  source.overrides.insert(source.overrides.end(), more.begin(), more.end());
  return load_scene_source(std::move(source));
}

std::vector<SceneOverride> read_overrides(const std::vector<std::string>& texts,
                                          FieldChecks& checks) {
  std::vector<SceneOverride> out;
  for (const std::string& text : texts) {
    try {
      out.push_back(parse_override(text));
    } catch (const InputError& e) {
      checks.problem("set", text, without_location(e.what()));
    }
  }
  return out;
}

std::vector<SceneOverride> run_length_overrides(const std::optional<QuantityInput>& duration,
                                                std::optional<std::int64_t> seed,
                                                FieldChecks& checks) {
  std::vector<SceneOverride> out;
  if (duration) {
    checks.quantity(*duration, Dimension::kTime, "duration");  // the unit, before the loader
    out.push_back({"world.duration", quantity_input_text(*duration)});
  }
  if (seed) out.push_back({"world.seed", std::to_string(*seed)});
  return out;
}

std::string shipped_scene(const std::string& relative) {
  if (std::filesystem::exists(relative)) return relative;
  return (std::filesystem::path(tools_dir()).parent_path() / relative).string();
}

}  // namespace fl
