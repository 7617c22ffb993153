// The regime the analytic model expects for a rig (the conditions in docs/physics.md and the
// friction law's closed forms in docs/friction-laws.md), to hold the simulation's own diagnosis
// (lab/run/regime_monitor.hpp) against.
#pragma once

#include <optional>
#include <string>

#include "core/friction_regime.hpp"
#include "core/regime.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

struct TheoryRegime {
  Regime regime = Regime::kOscillates;
  std::string reason;  // the condition that decides it, with its numbers
  // The friction law's prediction over the run's duration (core/friction_regime.hpp), when the
  // plate oscillates under friction at all: its stick-slip cycle, growth rate, stick time.
  std::optional<FrictionRegimePrediction> prediction;
};

// In order: rollers turning outward or l <= 2 mu_k h_c: no restoring force; an initial amplitude
// beyond l/2 - mu_k h_c: tips; a motor stalled by the plate's friction or rollers that stand
// still: sticks; otherwise what the friction law predicts at the rollers' surface speed (under
// load, for a driven rig; the slowest of a speed ramp) for the run's duration
// (predict_friction_regime): oscillates, clipped, stick-slip, grows, decays or tips.
TheoryRegime regime_from_theory(const CompiledRig& rig);

}  // namespace fl
