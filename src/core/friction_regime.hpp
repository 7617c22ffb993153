// Which motion a friction law gives a plate of amplitude A on rollers at surface speed v_r, from
// the closed forms (core/friction_oscillator.hpp, core/stick_slip_cycle.hpp; derivations in
// docs/friction-laws.md). Exact for a law without slip dependence and for a linear law
// (mu_s = mu_k, beta != 0); for a stribeck law with mu_s > mu_k it rests on the law linearised
// about v_r and the coulomb picture of the stick. Standard library only.
//
// A plate stuck to a roller never stays stuck for good while the law is positive at 2 v_r: it is
// carried toward the far roller, whose kinetic force grows with its load while the static limit
// shrinks with the near roller's, so the stick breaks at |x_b| < l/2. There is no such regime.
#pragma once

#include <limits>
#include <optional>

#include "core/friction_law.hpp"
#include "core/friction_oscillator.hpp"
#include "core/stick_slip_cycle.hpp"

namespace fl {

enum class FrictionRegime {
  kFullSlip,          // both rollers slip throughout; the amplitude steady (within the horizon)
  kGrows,             // both rollers slip; a falling law makes the amplitude grow, and within the
                      // horizon it neither reaches a roller's speed nor tips
  kDecays,            // a rising law makes the amplitude decay: the plate comes to rest at the
                      // centre (after one stick if it started above v_r / Omega)
  kClipped,           // one stick, then the amplitude v_r / Omega with the period unchanged
  kStickSlip,         // stick phases at +-v_r and slip arcs alternate for good
  kTips,              // a normal force reaches zero
  kNoRestoringForce,  // l <= 2 mu(v_r) h_c
};

// "full slip", "grows", "decays", "clipped", "stick-slip", "tips", "no restoring force".
const char* friction_regime_name(FrictionRegime regime);

struct FrictionRegimePrediction {
  FrictionRegime regime = FrictionRegime::kFullSlip;
  LinearisedMotion motion;      // mu(v_r), mu'(v_r), Omega, gamma, periods (not set without a
                                // restoring force)
  double margin = 0.0;          // v_r / (A Omega)
  double break_offset = 0.0;    // x_b [m]
  double tipping_offset = 0.0;  // l/2 - mu(v_r) h_c [m]
  // When the plate first reaches a roller's speed, from a turning point [s]: asin(margin) /
  // Omega within the first cycle, ln(margin) / gamma after growth; none if it never does.
  std::optional<double> stick_time;
  // When a growing amplitude reaches the tipping offset, ln(tipping / A) / gamma [s]; 0 when the
  // plate starts beyond it or the cycle it settles into reaches it.
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
