// Physically impossible or meaningless set-ups, found before any world is built.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace fl {

struct SceneProblem {
  std::string key;      // the scene key responsible, e.g. "plate.length"
  std::string message;  // what is wrong and what to do
};

// Every problem found, in the order the scene's keys are documented (empty: the scene is sound).
std::vector<SceneProblem> check_scene(const Scene& scene);

}  // namespace fl
