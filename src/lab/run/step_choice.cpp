#include "lab/run/step_choice.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/integrator_error.hpp"
#include "estimator/period_estimator.h"
#include "io/field_ref.hpp"
#include "lab/run/law_resolution.hpp"
#include "lab/run/regime_theory.hpp"
#include "scene/compiled_rig.hpp"
#include "sensor/hall_timing.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

double omega_of(const CompiledRig& rig) {
  if (!rig.omega)
    throw DomainError(describe("the scene has no oscillation (l = ", rig.rollers.spacing * 1e3,
                               " mm <= 2 mu_k h_c), so no step gives a period accuracy"));
  return *rig.omega;
}

void check_target(double target) {
  if (!(target > 0.0) || !std::isfinite(target))
    throw DomainError(
        describe(field_ref("accuracy"), " must be a positive fraction (e.g. 0.01%), got ", target));
}

// The Hall period's own error for the rig (none without a sensor or a pulse), refused when it
// alone takes more than its share of the target.
std::optional<HallTiming> sensor_timing(const CompiledRig& rig, double target) {
  std::optional<HallTiming> timing = predict_hall_timing(rig, fl_estimator::Config{}.min_amplitude);
  // A run too short for the estimator's two periods reports the trajectory's period instead.
  if (timing && timing->periods < 2) timing.reset();
  if (!timing || timing->period_error <= kSensorShareOfAccuracy * target) return timing;
  const double period = *rig.period_thick;
  // The periods that bring the error within its share, and the run that holds them.
  const double needed = (3.0 * timing->crossing_sd + 2.0 * timing->interpolation_bias) /
                        (kSensorShareOfAccuracy * target * period);
  const double duration = (std::ceil(needed) + 3.0) * period;
  throw DomainError(fmt::format(
      "the rig's estimator times each turning point to +-{:.3g} ms (the sensor's noise and the "
      "ADC's step over the signal's slope of {:.3g} counts/ms at its timing level), so over the {} "
      "periods of a {:.4g} s run its period is within +-{:.2g} % at best, more than {:.0f} % of "
      "the "
      "{:.3g} % asked: ask for a {} of at least {:.4g} s, a looser accuracy, or a faster "
      "sensor.sample_rate or quieter sensor.noise (a sweep can measure the trajectory's period "
      "alone: period: trajectory)",
      timing->crossing_sd * 1e3, timing->slope * 1e-3, timing->periods, rig.world.duration,
      timing->period_error * 100.0, kSensorShareOfAccuracy * 100.0, target * 100.0,
      field_ref("duration"), std::ceil(duration)));
}

// The largest step of the form 1/N s at most `dt_max`.
double whole_fraction_of_a_second(double dt_max) {
  return 1.0 / std::ceil(1.0 / dt_max);
}

}  // namespace

double predicted_integrator_bias(const Scene& scene) {
  return integrator_period_bias(omega_of(compile_rig(scene)), scene.world.time_step);
}

std::string step_basis_name(StepBasis basis) {
  switch (basis) {
    case StepBasis::kIntegratorBias:
      return "integrator bias";
    case StepBasis::kFrictionLaw:
      return "friction law";
    case StepBasis::kSceneStep:
      return "scene (fallback: no oscillation to size a step by)";
  }
  return "?";
}

StepChoice step_for_accuracy(const Scene& scene, double target) {
  return step_for_accuracy(compile_rig(scene), target);
}

StepChoice step_for_accuracy(const CompiledRig& rig, double target) {
  check_target(target);
  const double omega = omega_of(rig);
  StepChoice out;
  const std::optional<HallTiming> timing = sensor_timing(rig, target);
  if (timing) out.sensor_error = timing->period_error;
  const double integrator_share =
      kIntegratorShareOfAccuracy * target - out.sensor_error.value_or(0.0);
  out.time_step = whole_fraction_of_a_second(step_for_period_bias(omega, integrator_share));
  const double dt_bias = out.time_step;
  out.reason = fmt::format("{:.2e} predicted at Omega = {:.4g} rad/s",
                           integrator_period_bias(omega, out.time_step), omega);
  if (timing)
    out.reason += fmt::format(", beside the rig's estimator's {:.2e} over its {} periods",
                              timing->period_error, timing->periods);
  // What theory expects of the law over the run: whether the plate sticks, how fast the
  // amplitude grows or decays; the step must resolve what the plate will use.
  const TheoryRegime theory = regime_from_theory(rig);
  if (!theory.prediction) return out;
  const FrictionRegimePrediction& p = *theory.prediction;
  const bool sticks = p.stick_time.has_value() || p.regime == Regime::kClipped ||
                      p.regime == Regime::kStickSlip || p.regime == Regime::kSticks;
  std::optional<double> growth;
  if (rig.friction.depends_on_slip())
    growth = std::max(std::fabs(p.growth_rate), std::fabs(p.motion.gamma));
  if (const std::optional<UnresolvedLaw> law =
          unresolved_law(rig.friction, rig.gravity_normal, out.time_step, sticks, growth)) {
    out.time_step = whole_fraction_of_a_second(law->largest_step);
    out.basis = StepBasis::kFrictionLaw;
    out.reason = fmt::format("at the {:.4g} ms the bias allows, as theory expects this run: {}",
                             dt_bias * 1e3, law->reason);
  }
  return out;
}

StepChoice step_for_accuracy_or_scene(const CompiledRig& rig, double target) {
  check_target(target);
  if (rig.omega) return step_for_accuracy(rig, target);
  return StepChoice{rig.world.time_step, StepBasis::kSceneStep,
                    fmt::format("l - 2 mu_k h_c <= 0: no oscillation; the scene's {:.4g} ms",
                                rig.world.time_step * 1e3),
                    std::nullopt};
}

}  // namespace fl
