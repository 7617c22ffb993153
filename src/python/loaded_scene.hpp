// A scene as the Python module holds it: the lab's LoadedScene (shared, never changed: runs in
// several threads read it at once) with where it came from, so that it can be loaded again with
// more overrides (a run's duration and seed, Scene.with_set) through the very loader the command
// uses.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>

#include "lab/request/scene_source.hpp"
#include "scene/scene.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::python {

namespace py = pybind11;

// The lab's own (lab/request/scene_source.hpp): a Python Scene is a LoadedScene.
using fl::LoadedScene;
using fl::SceneSource;

// Overrides from a mapping {"rollers.spacing": "89mm", "friction.mu_k": 0.3} or a sequence of
// "key=value" texts (None: none).
std::vector<SceneOverride> overrides_argument(py::handle set);

// A run's scene argument: a Scene, or a path to load with no overrides.
using SceneArgument = std::variant<LoadedScene, std::filesystem::path>;
LoadedScene scene_argument(const SceneArgument& scene);
// Its source, to load again with a request's overrides.
SceneSource scene_source_argument(const SceneArgument& scene);

}  // namespace fl::python
