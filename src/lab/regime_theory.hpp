// The regime the analytic model expects for a scene (DESIGN.md's conditions), to hold the
// simulation's own diagnosis against.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace fl {

struct TheoryRegime {
  std::string regime;  // "oscillates", "sticks", "tips", "no restoring force"
  std::string reason;  // the condition that decides it, with its numbers
};

// In order: rollers turning outward or l <= 2 mu_k h_c: no restoring force; an initial amplitude
// beyond l/2 - mu_k h_c: tips; a roller surface speed below the plate's largest speed A omega:
// sticks; otherwise oscillates.
TheoryRegime regime_from_theory(const Scene& scene);

}  // namespace fl
