// Physically impossible or meaningless set-ups, found before any world is built.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "text/said.hpp"

namespace fl {

struct SceneProblem {
  std::string key;      // the scene key responsible, e.g. "plate.length"
  std::string message;  // what is wrong and what to do, in English
  Said said;            // the same as the catalogues say it (text/said.hpp)
  // The other keys whose values made it ("rollers.spacing", "plate.offset" for a plate too
  // short): where one of them was changed and `key` was not, the change is what to mend.
  std::vector<std::string> involves = {};
};

// Every problem found, in the order the scene's keys are documented (empty: the scene is sound).
std::vector<SceneProblem> check_scene(const Scene& scene);

}  // namespace fl
