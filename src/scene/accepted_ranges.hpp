// The values a scene accepts for the keys a student turns: the roller spacing, the rollers' speed
// (or the motor's duty under a drive), the plate's starting offset and the run's duration, each
// with every other value as the scene has it. A front end offers these ranges only, so a slider
// cannot reach a value check_scene (scene_checks.hpp) refuses.
//
// Found by bisection on check_scene itself, from the scene's own value (accepted) toward each
// bound of the key's search span: no second copy of the rules. That assumes the accepted values
// form one interval around the scene's, which each rule keeps (every rule on these keys is a
// bound on one side: the rollers' overlap, a restoring force, the plate's length, the drive's
// coupling span, the bench's plausible range, a step per quarter period).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace fl {

struct AcceptedRange {
  std::string key;   // the scene key, as `--set` takes it: "rollers.spacing"
  double least = 0;  // SI (duty: 0 to 1), accepted
  double most = 0;   // SI, accepted
  std::string unit;  // the SI unit of least and most ("m", "rad/s", "", "s")
};

// The ranges of the keys the scene has (rollers.speed without a drive, drive.motor.duty with
// one), in that order; a key whose own value the scene refuses (a scene that explores a
// breakdown) is left out.
std::vector<AcceptedRange> accepted_ranges(const Scene& scene);

}  // namespace fl
