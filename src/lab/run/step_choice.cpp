#include "lab/run/step_choice.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/describe.hpp"
#include "core/integrator_error.hpp"
#include "io/field_ref.hpp"
#include "lab/run/law_resolution.hpp"
#include "lab/run/regime_theory.hpp"
#include "scene/compiled_rig.hpp"

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
  out.time_step =
      whole_fraction_of_a_second(step_for_period_bias(omega, kIntegratorShareOfAccuracy * target));
  const double dt_bias = out.time_step;
  out.reason = fmt::format("{:.2e} predicted at Omega = {:.4g} rad/s",
                           integrator_period_bias(omega, out.time_step), omega);
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
                                rig.world.time_step * 1e3)};
}

}  // namespace fl
