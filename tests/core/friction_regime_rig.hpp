// The paper's rig as friction_regime_test and friction_regime_grid_test run it on the reference
// model (tests/support/reference_oscillator.hpp), and the regime a reference run shows, told in
// the predictor's terms (core/friction_regime.hpp).
#pragma once

#include <cmath>
#include <string>

#include "core/friction_regime.hpp"
#include "support/reference_oscillator.hpp"

namespace fl::test {

inline constexpr double kL = 0.089;
inline constexpr double kG = 9.81;
inline constexpr double kFast = 1.676;   // 1600 rpm on 10 mm rollers [m/s]
inline constexpr double kSlow = 0.2094;  // 200 rpm
inline constexpr double kHorizon = 20.0;
inline constexpr double kTolerance = 0.01;

inline FrictionLaw coulomb(double mu_k, double mu_s) {
  FrictionLaw law;
  law.mu_k = mu_k;
  law.mu_s = mu_s;
  return law;
}

inline FrictionLaw stribeck(double mu_s, double v_s, double beta) {
  FrictionLaw law;
  law.kind = FrictionLawKind::kStribeck;
  law.mu_k = 0.29;
  law.mu_s = mu_s;
  law.v_s = v_s;
  law.beta = beta;
  return law;
}

inline std::string describe_law(const FrictionLaw& law) {
  return (law.kind == FrictionLawKind::kCoulomb ? "coulomb mu_s " : "stribeck mu_s ") +
         std::to_string(law.mu_s) + " v_s " + std::to_string(law.v_s) + " beta " +
         std::to_string(law.beta);
}

// What the reference model's 20 s show, told in the predictor's terms: tipped; no stick and the
// last turning point within 1 % of the start (full slip), above (grows) or below (decays); sticks
// until the last quarter (stick-slip; clipped if every stick after the first has no length);
// sticks only early, then the amplitude shrinking (decays) or steady (clipped).
inline Regime observed_regime(const test::ReferenceRun& run, double amplitude) {
  if (run.tipped) return Regime::kTips;
  const auto sticks = test::stick_intervals(run);
  const auto turns = test::turning_points(run);
  if (sticks.empty()) {
    const double ratio = std::abs(turns.back().x) / amplitude;
    if (ratio > 1.0 + kTolerance) return Regime::kGrows;
    if (ratio < 1.0 - kTolerance) return Regime::kDecays;
    return Regime::kOscillates;
  }
  bool grazes_only = true;
  for (std::size_t i = 1; i < sticks.size(); ++i)
    grazes_only = grazes_only && sticks[i].end - sticks[i].start < 1e-9;
  if (sticks.size() > 1 && grazes_only) return Regime::kClipped;
  if (sticks.back().end > 0.75 * kHorizon) return Regime::kStickSlip;
  const auto later = test::turning_points(run, sticks.back().end);
  if (later.size() >= 2 &&
      std::abs(later.back().x) < (1.0 - kTolerance) * std::abs(later.front().x))
    return Regime::kDecays;
  return Regime::kClipped;
}

// What the reference model's 20 s do with `law` on the paper's rig (centre of mass h_c above the
// contact line, rollers' surface speed v_r), released at rest from kStart.
inline constexpr double kStart = 0.03;
inline Regime reference_regime(const FrictionLaw& law, double h_c, double v_r) {
  ReferenceRig rig;
  rig.spacing = kL;
  rig.h_c = h_c;
  rig.surface_speed = v_r;
  rig.gravity = kG;
  ReferenceOptions options;
  options.duration = kHorizon;
  return observed_regime(simulate_reference(law, rig, kStart, 0.0, options), kStart);
}

}  // namespace fl::test
