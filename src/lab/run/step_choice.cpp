#include "lab/run/step_choice.hpp"

#include <cmath>

#include "core/analytic_model.hpp"
#include "core/describe.hpp"
#include "core/integrator_error.hpp"
#include "io/field_ref.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {
namespace {

double omega_of(const Scene& scene) {
  const CompiledRig rig = compile_rig(scene);
  if (!rig.omega)
    throw DomainError(describe("the scene has no oscillation (l = ", rig.spacing * 1e3,
                               " mm <= 2 mu_k h_c), so no step gives a period accuracy"));
  return *rig.omega;
}

}  // namespace

double predicted_integrator_bias(const Scene& scene) {
  return integrator_period_bias(omega_of(scene), scene.world.time_step);
}

double step_for_accuracy(const Scene& scene, double target) {
  if (!(target > 0.0) || !std::isfinite(target))
    throw DomainError(
        describe(field_ref("accuracy"), " must be a positive fraction (e.g. 0.01%), got ", target));
  const double dt_max = step_for_period_bias(omega_of(scene), target);
  return 1.0 / std::ceil(1.0 / dt_max);
}

}  // namespace fl
