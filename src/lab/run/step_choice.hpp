// Choosing the time step from an accuracy target, by the integrator's measured error law:
// the semi-implicit Euler step shortens the period by (omega dt)^2 / 24 (docs/physics.md).
#pragma once

#include "scene/compiled_rig.hpp"
#include "scene/scene.hpp"

namespace fl {

// Relative period bias -(omega dt)^2 / 24 at the scene's time step (thick-plate omega).
double predicted_integrator_bias(const Scene& scene);

// The largest step of the form 1/N s (N whole) whose predicted |bias| is at most `target`
// (relative, e.g. 1e-4). Throws DomainError if the scene has no oscillation or target <= 0.
double step_for_accuracy(const Scene& scene, double target);
// The same for a rig already compiled (a run compiles its rig once).
double step_for_accuracy(const CompiledRig& rig, double target);

}  // namespace fl
