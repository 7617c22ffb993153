// The friction oscillator under a friction law beyond ideal Coulomb (core/friction_law.hpp): a
// plate on two rollers turning inward at surface speed v_r, centre of mass h_c above the contact
// line. Closed forms, derived in docs/friction-laws.md:
//
//   effective coefficient   mu = mu(v_r)  (both rollers slip at v_r when the plate is at rest)
//   angular frequency       Omega^2 = 2 g mu / (l - 2 mu h_c)
//   stick break             stuck to roller 0 (moving at +v_r), it breaks free at
//                           x_b = (l/2) (mu_s - mu(2 v_r)) / (mu_s + mu(2 v_r)), whatever h_c
//   full slip               v_r > A Omega(mu(v_r)): an oscillation of amplitude A never reaches
//                           a roller's speed; mu_s does not enter
//   growth rate             gamma = -g l mu'(v_r) / (2 (l - 2 mu h_c)), amplitude ~ exp(gamma t)
//   linearised period       T = 2 pi / sqrt(Omega^2 - gamma^2): no first-order change
//
// All quantities SI. Every function refuses inputs where it has no meaning with fl::DomainError
// (never a NaN). Standard library only.
#pragma once

#include "core/analytic_model.hpp"
#include "core/friction_law.hpp"

namespace fl {

// The plate on its rollers, as the closed forms see it.
struct PlateOnRollers {
  double spacing = 0.089;            // l, between the rollers' axes [m]
  double h_c = 0.0;                  // centre of mass above the contact line [m]
  double gravity = kDefaultGravity;  // [m/s^2]
};

// Refuses a law that means nothing at slip speeds in [0, max_slip]: a non-finite parameter,
// mu_k <= 0, mu_s < mu_k, v_s <= 0 (stribeck with mu_s > mu_k), or a kinetic coefficient <= 0
// somewhere in [0, max_slip] (a falling linear slope beta < 0 reaches zero at mu_k / |beta| and
// beyond).
void check_friction_law(const FrictionLaw& law, double max_slip);

// Refuses a plate that means nothing: l <= 0, h_c < 0, g <= 0, or a non-finite value.
void check_plate(const PlateOnRollers& plate);

// The effective kinetic coefficient mu(v_r): both rollers slip at v_r while the plate is at rest.
// Checks the law up to slip speed 2 v_r (the largest slip while |v| <= v_r).
double effective_mu(const FrictionLaw& law, double surface_speed);

// Omega = sqrt(2 g mu / (l - 2 mu h_c)) at mu = mu(v_r) [rad/s]; refuses l <= 2 mu h_c.
double sliding_angular_frequency(const FrictionLaw& law, const PlateOnRollers& plate,
                                 double surface_speed);

// Offset x_b at which a plate stuck to roller 0 (carried at +v_r) breaks free:
// x_b = (l/2) (mu_s - mu(2 v_r)) / (mu_s + mu(2 v_r)). A plate stuck to roller 1 (carried at
// -v_r) breaks free at -x_b. Negative when mu(2 v_r) > mu_s. Independent of h_c.
double stick_break_offset(const FrictionLaw& law, const PlateOnRollers& plate,
                          double surface_speed);

// Whether a plate at offset x stuck to roller `roller` (0 or 1) stays stuck: the far roller's
// kinetic force mu(2 v_r) N_far is at most mu_s N_stuck, with the normal forces of a plate under
// no net friction force, N_0 = m g (1/2 - x/l), N_1 = m g (1/2 + x/l). Refuses |x| >= l/2.
bool stick_holds(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                 int roller, double offset);

// The roller surface speed [m/s] above which an oscillation of amplitude A does not reach a
// roller's speed within its cycle: the first root of v = A Omega(mu(v)) (for coulomb, A Omega),
// found on a scan finer than the law's features and refined by bisection. The static limit mu_s
// does not enter (a plate that reaches v_r always sticks, whatever mu_s); a slip-dependent law
// enters through mu(v) in Omega, and through the growth rate: a growing oscillation (gamma > 0)
// reaches the roller's speed later at any v_r, a decaying one that starts below never does.
double full_slip_surface_speed(const FrictionLaw& law, const PlateOnRollers& plate,
                               double amplitude);

// The same as the rollers' angular speed [rad/s]: full_slip_surface_speed / a.
double full_slip_roller_speed(const FrictionLaw& law, const PlateOnRollers& plate, double amplitude,
                              double roller_radius);

// v_r / (A Omega(mu(v_r))): > 1 means an oscillation of amplitude A slips throughout its cycle.
double full_slip_margin(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                        double amplitude);

// The motion of a slipping plate with the law linearised about the rollers' surface speed:
// mu(v_r -+ v) = mu -+ mu' v, which gives x'' - 2 gamma x' + Omega^2 x = 0.
struct LinearisedMotion {
  double mu = 0.0;        // mu(v_r), the effective mu_k
  double slope = 0.0;     // mu'(v_r) [s/m]
  double omega = 0.0;     // Omega = sqrt(2 g mu / (l - 2 mu h_c)) [rad/s]
  double gamma = 0.0;     // e-folding rate of the amplitude, -g l mu' / (2 (l - 2 mu h_c)) [1/s]
  double period = 0.0;    // 2 pi / sqrt(Omega^2 - gamma^2) [s]
  double period_0 = 0.0;  // 2 pi / Omega, the coulomb period at mu(v_r) [s]
};

// Refuses l <= 2 mu h_c and |gamma| >= Omega (no oscillation: the plate creeps, not oscillates).
LinearisedMotion linearised_motion(const FrictionLaw& law, const PlateOnRollers& plate,
                                   double surface_speed);

}  // namespace fl
