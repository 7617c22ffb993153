// The regime the analytic model expects for a rig (the conditions in docs/physics.md), to hold
// the simulation's own diagnosis (lab/regime_monitor.hpp) against.
#pragma once

#include <string>

#include "core/regime.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

struct TheoryRegime {
  Regime regime = Regime::kOscillates;  // oscillates, sticks, tips or no restoring force
  std::string reason;                   // the condition that decides it, with its numbers
};

// In order: rollers turning outward or l <= 2 mu_k h_c: no restoring force; an initial amplitude
// beyond l/2 - mu_k h_c: tips; a motor stalled by the plate's friction, or a roller surface
// speed below the plate's largest speed A omega: sticks; otherwise oscillates.
TheoryRegime regime_from_theory(const CompiledRig& rig);

}  // namespace fl
