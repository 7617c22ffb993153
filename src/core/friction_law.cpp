#include "core/friction_law.hpp"

#include <cmath>

namespace fl {

double FrictionLaw::kinetic(double slip_speed) const {
  if (kind == FrictionLawKind::kCoulomb) return mu_k;
  const double r = slip_speed / v_s;
  return mu_k + (mu_s - mu_k) * std::exp(-r * r) + beta * slip_speed;
}

double FrictionLaw::slope(double slip_speed) const {
  if (kind == FrictionLawKind::kCoulomb) return 0.0;
  const double r = slip_speed / v_s;
  return -2.0 * (mu_s - mu_k) * r / v_s * std::exp(-r * r) + beta;
}

bool FrictionLaw::depends_on_slip() const {
  return kind == FrictionLawKind::kStribeck && (mu_s != mu_k || beta != 0.0);
}

}  // namespace fl
