// A run's cycles (core/cycle_tracker.hpp) as the table `run --out DIR` writes to cycles.csv and a
// sweep with `cycles: true` writes per point: each cycle's measured period, amplitude, rollers'
// speed and stick time, which way a ramp was going, and beside them what theory says at that
// cycle's mean surface speed (core/friction_oscillator.hpp, core/stick_slip_cycle.hpp).
#pragma once

#include <string>
#include <vector>

#include "core/cycle_tracker.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// "up", "down" or "hold": the sign of the ramp's slope (speed or duty) at the cycle's middle;
// "hold" for a run without a ramp.
std::string ramp_direction(const CompiledRig& rig, const CycleRecord& cycle);

// The CSV text, a header and one row per cycle (columns in docs/scene-format.md, "The cycles").
// Deterministic: the same cycles give the same bytes.
std::string cycles_csv(const CompiledRig& rig, const std::vector<CycleRecord>& cycles);

}  // namespace fl
