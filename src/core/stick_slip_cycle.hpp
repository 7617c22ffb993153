// The stick-slip limit cycle of a plate under coulomb friction with a static limit mu_s >= mu_k
// (docs/friction-laws.md). Once the plate has reached a roller's surface speed, it moves with
// that roller from -x_b to +x_b, slips along a harmonic arc (angular frequency Omega at mu_k)
// out to its amplitude and back until it meets the other roller's speed at +x_b, moves with that
// roller to -x_b, and so on:
//
//   x_b = (l/2) (mu_s - mu_k) / (mu_s + mu_k)     A = sqrt(x_b^2 + (v_r / Omega)^2)
//   stick  2 x_b / v_r    slip arc  (2 / Omega) atan(v_r / (Omega x_b))    T = 2 (stick + slip)
//
// For mu_s = mu_k (x_b = 0) this is the clipped cycle: amplitude v_r / Omega, period 2 pi / Omega,
// touching each roller's speed for an instant. Standard library only.
#pragma once

#include "core/friction_law.hpp"
#include "core/friction_oscillator.hpp"

namespace fl {

struct StickSlipCycle {
  double omega = 0.0;           // Omega of the slip arcs, at mu_k [rad/s]
  double break_offset = 0.0;    // x_b: stick to roller 0 ends at +x_b, to roller 1 at -x_b [m]
  double amplitude = 0.0;       // the largest |x|, sqrt(x_b^2 + (v_r / Omega)^2) [m]
  double stick_duration = 0.0;  // one stick episode, 2 x_b / v_r (two per period) [s]
  double slip_duration = 0.0;   // one slip arc, (2 / Omega) atan2(v_r, Omega x_b) [s]
  double period = 0.0;          // 2 (stick_duration + slip_duration) [s]
  bool clipped = false;         // mu_s == mu_k: no stick phase, the amplitude clipped to v_r/Omega
};

// The cycle for a law without slip dependence (coulomb, or a stribeck law with mu_s = mu_k and
// beta = 0) at roller surface speed v_r. Refuses a slip-dependent law (no closed form) and a
// cycle whose amplitude reaches the tipping offset l/2 - mu_k h_c.
StickSlipCycle stick_slip_cycle(const FrictionLaw& law, const PlateOnRollers& plate,
                                double surface_speed);

// The first stick of a harmonic oscillation of amplitude A0 > v_r / Omega (same law as above),
// counted from a turning point at x = -A0: the plate reaches roller 0's speed at
// x_e = -sqrt(A0^2 - (v_r / Omega)^2) after asin(v_r / (A0 Omega)) / Omega, then moves with
// the roller to x_b, which puts it on the cycle. (From x = +A0: roller 1, mirrored.)
struct FirstStick {
  double time_to_stick = 0.0;  // from the turning point to the stick [s]
  double entry_offset = 0.0;   // x_e [m], < 0
  double duration = 0.0;       // (x_b - x_e) / v_r [s]
};

// Refuses A0 <= v_r / Omega (the plate never sticks) and A0 at or beyond the tipping offset.
FirstStick first_stick(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                       double amplitude);

}  // namespace fl
