// A request's scene: a file or a text, the overrides after it (the `set` field, a run's
// `duration` and `seed`), and the asset folder its named parts come from. Every front end loads
// it here, through the one loader (scene/scene_yaml.hpp); a loaded scene keeps its source, so
// that it can be loaded again with more overrides.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lab/request/field_checks.hpp"
#include "scene/scene.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

// A scene the lab ships, for a request that names none (`relative`: "scenes/minimal.yaml"): from
// the working folder when it holds one, else from the source tree.
std::string shipped_scene(const std::string& relative);

struct SceneSource {
  std::string file;  // the scene file; empty for a text
  std::string text;  // the scene's text, when it is given as text
  std::string name;  // stands for the file in messages, for a text
  std::vector<SceneOverride> overrides;
  std::string asset_dir;  // the request's `assets` field (lab/request/lab_data.hpp)
};

// A scene loaded, never changed afterwards (runs in several threads read it at once).
struct LoadedScene {
  std::shared_ptr<const Scene> scene;
  SceneSource source;
};

// Loads (or loads again) a scene; throws InputError located in the file or at the override.
LoadedScene load_scene_source(SceneSource source);

// The same scene with more overrides after its own (a later one wins).
LoadedScene with_overrides(const LoadedScene& scene, const std::vector<SceneOverride>& more);

// Reads "key.path=value" texts (the `set` field) into overrides, each problem by field.
std::vector<SceneOverride> read_overrides(const std::vector<std::string>& texts,
                                          FieldChecks& checks);

// The overrides a run's `duration` and `seed` fields stand for (world.duration, world.seed);
// the duration's unit checked.
std::vector<SceneOverride> run_length_overrides(const std::optional<QuantityInput>& duration,
                                                std::optional<std::int64_t> seed,
                                                FieldChecks& checks);

}  // namespace fl
