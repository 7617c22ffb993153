// The stability catalogue: stiff and extreme scenes (scenes/extreme/), each run at its own step
// and diagnosed, against the regime theory expects; the largest trustworthy time step found by
// bisection; the period error at the scene's step; and how errors in T and l carry into mu_k.
#pragma once

#include <optional>
#include <string>

#include "core/regime.hpp"
#include "scene/scene.hpp"

namespace fl {

struct StabilityRow {
  std::string name;
  std::string parameters;  // the case in a few words (mu_k, l, h_c, speed, amplitude, dt)
  Regime expected = Regime::kOscillates;  // from theory (regime_from_theory)
  std::string expected_reason;
  std::optional<Regime> declared;      // the scene's expect.regime
  Regime found = Regime::kOscillates;  // diagnosed by the run at the scene's step
  std::string evidence;
  int solver_iterations = 0;  // what the run at the scene's step ended with (the scene's, or
                              // raised when its solver did not converge)
  std::optional<std::string> solver_iterations_raised;  // from what, to what, why
  bool as_expected = false;  // found == expected (and == declared, if any)
  // Largest step in [1e-5 s, 1/60 s] at which the run is trustworthy: no numerical failure, the
  // expected regime, and (for an oscillation) the period within 0.1 % of the thick formula (for a
  // stick-slip cycle, of its closed form; a clipped amplitude within 1 % of v_r / Omega).
  std::optional<double> largest_step;  // s
  std::string step_note;               // when there is none, or every step tried was fine
  // Relative to the thick formula, at the scene's step (none for rollers that warm or run out).
  std::optional<double> period_error;
  double condition_period = 0.0;  // d ln mu_k / d ln T through the thick formula
  double condition_spacing = 0.0;
  double condition_h_c = 0.0;
  double wall_s = 0.0;  // for this case, bisection included
};

// A step is trustworthy when the period is within this of the thick formula.
inline constexpr double kTrustworthyPeriodError = 1e-3;
// A clipped cycle's amplitude is trustworthy within this of v_r / Omega.
inline constexpr double kTrustworthyAmplitudeError = 1e-2;

StabilityRow run_stability_case(const Scene& scene);

}  // namespace fl
