// Choosing the time step from an accuracy target. The period's error has two predictable parts
// (docs/physics.md): the semi-implicit Euler step shortens the period by (omega dt)^2 / 24, and a
// step too coarse for the friction law (a Stribeck drop stepped over at a breakaway, a growth or
// decay faster than the step) makes the run the step's rather than the law's
// (lab/run/law_resolution.hpp). The chosen step meets both.
#pragma once

#include <optional>
#include <string>

#include "scene/compiled_rig.hpp"
#include "scene/scene.hpp"

namespace fl {

// Relative period bias -(omega dt)^2 / 24 at the scene's time step (thick-plate omega).
double predicted_integrator_bias(const Scene& scene);

// What sized a chosen step.
enum class StepBasis {
  kIntegratorBias,  // the integrator's period bias reaches the target at this step
  kFrictionLaw,     // the friction law needs a finer step than the bias allows
  kSceneStep,       // fallback: no oscillation to size a step by, the scene's own step is kept
};
// "integrator bias", "friction law", "scene (fallback: no oscillation to size a step by)".
std::string step_basis_name(StepBasis basis);

struct StepChoice {
  double time_step = 0.0;  // s, of the form 1/N s (N whole) unless the scene's own
  StepBasis basis = StepBasis::kIntegratorBias;
  std::string reason;  // the numbers behind it
  // What the rig's estimator adds to the Hall period's error, whatever the step (relative, its
  // bound: sensor/hall_timing.hpp); none without a sensor or a pulse to time.
  std::optional<double> sensor_error;
};

// The share of an accuracy target the integrator's predicted bias may take; the rest is kept for
// what the prediction leaves out (its higher orders, a period read from a finite run: at 1e-4,
// spacing sweeps at the full target measured errors up to 1.0003e-4).
inline constexpr double kIntegratorShareOfAccuracy = 0.9;

// The most of an accuracy target the Hall period's own error (the sensor's and the estimator's
// timing, which no step changes) may take, leaving the integrator at least a tenth; beyond it the
// target is refused.
inline constexpr double kSensorShareOfAccuracy = 0.8;

// The largest step of the form 1/N s (N whole) whose predicted |bias| is at most
// kIntegratorShareOfAccuracy * `target` (relative, e.g. 1e-4) less the rig's sensor error (a rig
// with a Hall sensor reports the estimator's period, which carries both), and that resolves the
// friction law where theory expects the plate to use it (its sticks, its growth:
// lab/run/regime_theory.hpp). Throws DomainError if the rig has no oscillation, target <= 0, or the
// sensor's error alone exceeds kSensorShareOfAccuracy of the target (saying what would meet it).
StepChoice step_for_accuracy(const CompiledRig& rig, double target);
// The same for a scene, compiled first.
StepChoice step_for_accuracy(const Scene& scene, double target);
// For a sweep point, which must not stop the sweep: a rig with no oscillation keeps its scene's
// step (StepBasis::kSceneStep, saying so). Throws DomainError for target <= 0 only.
StepChoice step_for_accuracy_or_scene(const CompiledRig& rig, double target);

}  // namespace fl
