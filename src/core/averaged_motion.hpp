// The slipping plate's motion averaged over one cycle (Krylov-Bogoliubov), for a friction law
// that is not linear in the slip speed near the rollers' surface speed (docs/friction-laws.md).
// While both rollers slip (|v| < v_r) the plate obeys
//
//   x'' = -Omega^2(v) x + F(v),   F(v) = g l delta(v) / (l - 2 h_c sigma(v)),
//   Omega^2(v) = 2 g sigma(v) / (l - 2 h_c sigma(v)),
//   sigma(v) = (mu(v_r - v) + mu(v_r + v)) / 2,   delta(v) = (mu(v_r - v) - mu(v_r + v)) / 2,
//
// and on a cycle x = A cos(theta), v = -A Omega_0 sin(theta) (Omega_0 = Omega(0)) the amplitude
// and phase drift, to first order in F and in Omega^2(v) - Omega_0^2, as
//
//   gamma(A) = (1 / (2 pi V)) Int_0^2pi F(V sin t) sin t dt              (V = A Omega_0)
//   omega(A) = Omega_0 + (1 / (2 pi Omega_0)) Int_0^2pi (Omega^2(V sin t) - Omega_0^2) cos^2 t dt
//
// gamma(A) -> the linearised rate as A -> 0. The integrals are evaluated by the trapezoidal rule
// (periodic integrands: it converges geometrically), refined until it settles. Standard library
// only.
#pragma once

#include "core/friction_law.hpp"
#include "core/friction_oscillator.hpp"

namespace fl {

// The amplitude's averaged e-folding rate gamma(A) [1/s] of a slipping plate of amplitude A.
// Refuses A <= 0 and A > v_r / Omega_0 (such a cycle reaches a roller's speed), and a law or
// plate the slip motion has no meaning for.
double averaged_growth_rate(const FrictionLaw& law, const PlateOnRollers& plate,
                            double surface_speed, double amplitude);

// The period 2 pi / sqrt(omega(A)^2 - gamma(A)^2) [s] of a slipping plate of amplitude A (same
// domain; the gamma^2 term is the damped oscillator's, exact for a linear law).
double averaged_period(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                       double amplitude);

// The energy per unit mass [m^2/s^2] the slip arc gains between two sticks: the harmonic arc of
// amplitude A_1 = sqrt(x_b^2 + (v_r / Omega_0)^2) from (x_b, v_r) over its turning point to
// (x_b, -v_r), Int F(v) v dt = A_1 Int_{-t1}^{t1} F(A_1 Omega_0 sin t) sin t dt with
// t1 = atan2(v_r, Omega_0 x_b). Refuses x_b <= 0 (the arc has no such shape).
double slip_arc_energy_gain(const FrictionLaw& law, const PlateOnRollers& plate,
                            double surface_speed);

}  // namespace fl
