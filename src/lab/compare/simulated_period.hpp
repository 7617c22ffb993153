// The period one simulation of a scene gives, as the experiments that set a scene's mu_k (and
// spacing) and compare periods read it (compare, fit --through-rig): the rig's estimator's
// period, or the trajectory's where the estimator accepted none (then without a spread, and the
// source says so), with the regime that decides whether there is a period at all.
#pragma once

#include <optional>
#include <string>

#include "core/regime.hpp"
#include "scene/scene.hpp"

namespace fl {

struct SimulatedPeriod {
  std::optional<double> period;      // s
  std::optional<double> period_std;  // s, standard deviation of the estimator's periods
  // s, the standard error of their mean (two accepted periods or more)
  std::optional<double> period_std_error;
  bool from_trajectory = false;  // the estimator accepted no period: the trajectory's instead
  std::optional<Regime> regime;
  std::string evidence;                // what showed the regime
  std::optional<std::string> failure;  // a guard's message when one stopped the run

  // A harmonic regime with a positive period.
  bool oscillates() const;
  // Why there is no period to use, for a message (only meaningful when !oscillates()).
  std::string no_oscillation_reason() const;
  // "hall estimator", "trajectory (the estimator accepted no period)", or "" without a period.
  std::string source() const;
};

// Runs the scene (its own duration) and reads its period.
SimulatedPeriod simulate_period(const Scene& scene);

// The scene with mu_k set as a number (no longer the paper's material) and, when given, the
// rollers' spacing [m]; checked as the loader checks a scene (std::runtime_error naming the key
// otherwise).
Scene scene_with_mu_k(const Scene& scene, double mu_k, std::optional<double> spacing = {});

}  // namespace fl
