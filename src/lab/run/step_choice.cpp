#include "lab/run/step_choice.hpp"

#include <cmath>

#include "core/analytic_model.hpp"
#include "core/describe.hpp"
#include "core/integrator_error.hpp"
#include "io/field_ref.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {
namespace {

double omega_of(const CompiledRig& rig) {
  if (!rig.omega)
    throw DomainError(describe("the scene has no oscillation (l = ", rig.rollers.spacing * 1e3,
                               " mm <= 2 mu_k h_c), so no step gives a period accuracy"));
  return *rig.omega;
}

}  // namespace

double predicted_integrator_bias(const Scene& scene) {
  return integrator_period_bias(omega_of(compile_rig(scene)), scene.world.time_step);
}

double step_for_accuracy(const Scene& scene, double target) {
  return step_for_accuracy(compile_rig(scene), target);
}

double step_for_accuracy(const CompiledRig& rig, double target) {
  if (!(target > 0.0) || !std::isfinite(target))
    throw DomainError(
        describe(field_ref("accuracy"), " must be a positive fraction (e.g. 0.01%), got ", target));
  const double dt_max = step_for_period_bias(omega_of(rig), target);
  return 1.0 / std::ceil(1.0 / dt_max);
}

}  // namespace fl
