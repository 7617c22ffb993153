#include "core/tilted_rig.hpp"

#include <cmath>
#include <numbers>

#include "core/analytic_model.hpp"
#include "core/domain_check.hpp"

namespace fl {

double gravity_normal(double gravity, double tilt) {
  return gravity * std::cos(tilt);
}

double oscillation_centre(double spacing, double mu_k, double h_c, double tilt) {
  if (!has_restoring_force(spacing, mu_k, h_c))
    throw DomainError("no restoring force (l <= 2 mu_k h_c): the oscillation has no centre");
  if (!(std::fabs(tilt) < 0.5 * std::numbers::pi))
    throw DomainError("a tilt must be below 90 degrees either way");
  return -(spacing - 2.0 * mu_k * h_c) * std::tan(tilt) / (2.0 * mu_k) + 0.0;  // + 0: no -0
}

double oscillation_centre(double spacing, double mu_0, double mu_1, double h_c, double tilt) {
  if (mu_0 == mu_1) return oscillation_centre(spacing, mu_0, h_c, tilt);
  const double sum = mu_0 + mu_1;
  if (!(sum > 0.0) || !(spacing > sum * h_c))
    throw DomainError("no restoring force (l <= (mu_0 + mu_1) h_c): the oscillation has no centre");
  if (!(std::fabs(tilt) < 0.5 * std::numbers::pi))
    throw DomainError("a tilt must be below 90 degrees either way");
  const double t = std::tan(tilt);
  return h_c * t - 0.5 * spacing * ((mu_1 - mu_0) + 2.0 * t) / sum + 0.0;
}

}  // namespace fl
