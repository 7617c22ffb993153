#include "core/friction_law.hpp"

#include <cmath>

namespace fl {

const char* friction_law_kind_name(FrictionLawKind kind) {
  return kind == FrictionLawKind::kStribeck ? "stribeck" : "coulomb";
}

std::optional<FrictionLawKind> friction_law_kind_from_name(std::string_view name) {
  for (const FrictionLawKind k : {FrictionLawKind::kCoulomb, FrictionLawKind::kStribeck})
    if (name == friction_law_kind_name(k)) return k;
  return std::nullopt;
}

double FrictionLaw::kinetic(double slip_speed) const {
  if (kind == FrictionLawKind::kCoulomb) return mu_k;
  double mu = mu_k + beta * slip_speed;
  // Without a static excess the Stribeck term is zero (and v_s may be unset).
  if (mu_s != mu_k) {
    const double r = slip_speed / v_s;
    mu += (mu_s - mu_k) * std::exp(-r * r);
  }
  return mu;
}

double FrictionLaw::slope(double slip_speed) const {
  if (kind == FrictionLawKind::kCoulomb) return 0.0;
  double slope = beta;
  if (mu_s != mu_k) {
    const double r = slip_speed / v_s;
    slope -= 2.0 * (mu_s - mu_k) * r / v_s * std::exp(-r * r);
  }
  return slope;
}

bool FrictionLaw::depends_on_slip() const {
  return kind == FrictionLawKind::kStribeck && (mu_s != mu_k || beta != 0.0);
}

}  // namespace fl
