// Whether a run's time step resolves the friction law where the plate used it. Two features of a
// law can be narrower than a step:
//
//   the Stribeck drop  (mu_s > mu_k, stribeck): the coefficient falls from mu_s to mu_k within a
//       slip speed of about v_s. A plate that sticks passes through it at every breakaway, and
//       one step changes the slip speed by up to mu_s g dt: the drop is resolved when
//       mu_s g dt <= v_s, i.e. dt <= v_s / (mu_s g). A plate that never sticks never enters it.
//   the growth or decay (a slip-dependent law): the amplitude e-folds at rate gamma; the
//       integrator's error per step grows with (gamma dt)^2, and the rate is resolved when
//       |gamma| dt <= kLargestGrowthPerStep.
//
// A run whose step does not resolve what it used is diagnosed numerically failed, naming the
// step that would (lab/run/regime_monitor.hpp). Standard library and fmt.
#pragma once

#include <optional>
#include <string>

#include "core/friction_law.hpp"

namespace fl {

// The largest |gamma| dt a run may take.
inline constexpr double kLargestGrowthPerStep = 0.01;

struct UnresolvedLaw {
  double largest_step = 0.0;  // s, the step that would resolve it
  std::string reason;         // the feature, its size and the step's
};

// `stuck` whether the plate stuck to a roller in the run; `growth_rate` the amplitude's measured
// e-folding rate [1/s], if any.
std::optional<UnresolvedLaw> unresolved_law(const FrictionLaw& law, double gravity,
                                            double time_step, bool stuck,
                                            std::optional<double> growth_rate);

}  // namespace fl
