// Rollers warming after liquid nitrogen: the paper cooled its PVC tubes in liquid nitrogen and
// measured at 77 K "for a few tens of seconds" while they stayed cold. The tubes start at T0,
// stay there while the nitrogen inside them lasts (a hold), then warm toward the room with one
// time constant (a lumped wall, Newton's law of cooling):
//
//   T(t) = T0                                          t <= hold
//   T(t) = T_room - (T_room - T0) exp(-(t - hold)/tau)  t >  hold
//
// The paper gives mu_k only at its two ends (77 K and 300 K). Between them the lab assumes mu_k
// linear in the tube's temperature, through (T0, mu0) and (T_room, mu_room): the simplest law that
// meets both measurements, with no transition the paper did not see (docs/physics.md).
// Standard library only.
#pragma once

namespace fl {

class RollerWarming {
 public:
  // Temperatures in K (0 < start < room), hold and tau in s (hold >= 0, tau > 0), the kinetic
  // coefficients at the start and at the room's temperature (> 0). Refuses others
  // (fl::DomainError).
  RollerWarming(double start_temperature, double room_temperature, double time_constant,
                double hold, double mu_k_start, double mu_k_room);

  // The tubes' temperature [K] at time t [s].
  double temperature(double t) const;
  // mu_k at temperature T [K] (linear between the two ends; held at either end beyond them).
  double mu_k_at_temperature(double temperature) const;
  // mu_k at time t [s].
  double mu_k(double t) const { return mu_k_at_temperature(temperature(t)); }

  double start_temperature() const { return start_; }
  double room_temperature() const { return room_; }
  double time_constant() const { return tau_; }
  double hold() const { return hold_; }
  double mu_k_start() const { return mu_start_; }
  double mu_k_room() const { return mu_room_; }

 private:
  double start_, room_, tau_, hold_, mu_start_, mu_room_;
};

}  // namespace fl
