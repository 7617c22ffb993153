// Which motion a friction law gives a plate of amplitude A on rollers at surface speed v_r, from
// the closed forms (core/friction_oscillator.hpp, core/stick_slip_cycle.hpp) and the averaged
// motion (core/averaged_motion.hpp); derivations in docs/friction-laws.md. Exact for a law
// without slip dependence; for a slip-dependent law it rests on the cycle-averaged growth rate
// gamma(A) (first order in the law's departure from coulomb at v_r) and on the energy balance of
// the slip arc between two sticks. Standard library only.
//
// A plate stuck to a roller never stays stuck for good while the law is positive at 2 v_r: it is
// carried toward the far roller, whose kinetic force grows with its load while the static limit
// shrinks with the near roller's, so the stick breaks at |x_b| < l/2. There is no such regime.
#pragma once

#include <limits>
#include <optional>

#include "core/friction_law.hpp"
#include "core/friction_oscillator.hpp"
#include "core/regime.hpp"
#include "core/stick_slip_cycle.hpp"

namespace fl {

struct FrictionRegimePrediction {
  // oscillates (full slip at a steady amplitude: the start's, or settled_amplitude, a slip
  // cycle where gamma(A) = 0), grows, decays (to a smaller cycle, or to rest at the centre after a
  // stick if it started above v_r / Omega), clipped, stick-slip, tips or no restoring force.
  Regime regime = Regime::kOscillates;
  LinearisedMotion motion;      // mu(v_r), mu'(v_r), Omega, gamma at A -> 0, periods (not set
                                // without a restoring force)
  double margin = 0.0;          // v_r / (A Omega)
  double break_offset = 0.0;    // x_b [m]
  double tipping_offset = 0.0;  // l/2 - mu(v_r) h_c [m]
  double growth_rate = 0.0;     // gamma(A) at the start amplitude (0 when A > v_r / Omega) [1/s]
  // The amplitude of the slip cycle the motion settles into, where gamma(A) changes sign from
  // growth below to decay above [m]; none when it settles elsewhere.
  std::optional<double> settled_amplitude;
  // When the plate first reaches a roller's speed [s]: from a turning point, asin(margin) /
  // Omega within the first cycle; the averaged growth time Int dA / (A gamma(A)) otherwise.
  std::optional<double> stick_time;
  // When the plate tips [s]: 0 when it starts beyond the tipping offset; the averaged growth
  // time when a growing amplitude reaches it while slipping; the first stick's time when the
  // slip arc after that stick swings beyond it (it tips within that arc).
  std::optional<double> tip_time;
  // The cycle after the first stick, for a law without slip dependence.
  std::optional<StickSlipCycle> cycle;
};

// The regime over a run of duration `horizon` [s] (+infinity: where the motion ends up). A
// growth or decay counts when the amplitude changes by more than the fraction
// `steady_tolerance` within the horizon. Refuses the inputs the closed forms refuse.
FrictionRegimePrediction predict_friction_regime(
    const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed, double amplitude,
    double horizon = std::numeric_limits<double>::infinity(), double steady_tolerance = 0.01);

}  // namespace fl
