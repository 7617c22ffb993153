// The friction between the plate and a roller as one value: a kinetic coefficient that may depend
// on the contact's slip speed, and the static limit a contact with no slip holds to.
//
//   coulomb:   mu(s) = mu_k                                             static limit mu_s >= mu_k
//   stribeck:  mu(s) = mu_k + (mu_s - mu_k) exp(-(s / v_s)^2) + beta s  static limit mu_s
//
// s >= 0 is the slip speed [m/s]; beta [s/m] has any sign (beta alone with mu_s = mu_k is a
// linear law). Standard library only.
#pragma once

#include <optional>
#include <string_view>

namespace fl {

enum class FrictionLawKind { kCoulomb, kStribeck };

// "coulomb", "stribeck"; and the kind a name stands for, or nullopt.
const char* friction_law_kind_name(FrictionLawKind kind);
std::optional<FrictionLawKind> friction_law_kind_from_name(std::string_view name);

struct FrictionLaw {
  FrictionLawKind kind = FrictionLawKind::kCoulomb;
  double mu_k = 0.29;  // kinetic coefficient (at large slip for stribeck, beta = 0)
  double mu_s = 0.29;  // static limit, >= mu_k
  double v_s = 0.0;    // m/s, the Stribeck speed (stribeck only; > 0)
  double beta = 0.0;   // s/m, the linear slope (stribeck only)

  // The kinetic coefficient at slip speed s [m/s], s >= 0.
  double kinetic(double slip_speed) const;
  // d mu / d s at slip speed s [s/m].
  double slope(double slip_speed) const;
  // Whether mu depends on the slip speed at all.
  bool depends_on_slip() const;
};

}  // namespace fl
