#include "lab/step_choice.hpp"

#include <cmath>
#include <numbers>

#include "core/analytic_model.hpp"
#include "core/describe.hpp"

namespace fl {
namespace {

double omega_of(const Scene& scene) {
  return angular_frequency(scene.rollers.spacing, scene.friction.mu_k, plate_mass(scene).h_c,
                           scene.world.gravity);
}

}  // namespace

double predicted_integrator_bias(const Scene& scene) {
  const double omega_dt = omega_of(scene) * scene.world.time_step;
  return -omega_dt * omega_dt / 24.0;
}

double step_for_accuracy(const Scene& scene, double target) {
  if (!(target > 0.0) || !std::isfinite(target))
    throw DomainError(
        describe("--accuracy must be a positive fraction (e.g. 0.01%), got ", target));
  const double dt_max = std::sqrt(24.0 * target) / omega_of(scene);
  return 1.0 / std::ceil(1.0 / dt_max);
}

}  // namespace fl
