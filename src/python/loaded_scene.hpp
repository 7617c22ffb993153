// A scene as the Python module holds it: the loaded Scene (shared, never changed: runs in several
// threads read it at once) and where it came from, so that it can be loaded again with more
// overrides (a run's duration and seed, Scene.with_set) through the very loader the command uses.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>

#include "scene/scene.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::python {

namespace py = pybind11;

struct SceneSource {
  std::string file;  // the scene file, or empty for text
  std::string text;  // the scene's text, when it was given as text
  std::string name;  // stands for the file in messages, for text
  std::vector<SceneOverride> overrides;
  std::string asset_dir;
};

struct LoadedScene {
  std::shared_ptr<const Scene> scene;
  SceneSource source;
};

// Loads (or loads again) a scene; throws InputError.
LoadedScene load_scene_source(SceneSource source);

// The same scene with more overrides after its own (a later one wins).
LoadedScene with_overrides(const LoadedScene& scene, const std::vector<SceneOverride>& more);

// Overrides from a mapping {"rollers.spacing": "89mm", "friction.mu_k": 0.3} or a sequence of
// "key=value" texts (None: none).
std::vector<SceneOverride> overrides_argument(py::handle set);

// A run's scene argument: a Scene, or a path to load with no overrides.
using SceneArgument = std::variant<LoadedScene, std::filesystem::path>;
LoadedScene scene_argument(const SceneArgument& scene);

}  // namespace fl::python
