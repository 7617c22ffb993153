#include "lab/compare/simulated_period.hpp"

#include <stdexcept>
#include <vector>

#include "lab/run/experiment.hpp"
#include "scene/scene_checks.hpp"

namespace fl {

bool SimulatedPeriod::oscillates() const {
  return !failure && regime && regime_is_harmonic(*regime) && period && *period > 0.0;
}

std::string SimulatedPeriod::no_oscillation_reason() const {
  if (failure) return "the run failed: " + *failure;
  if (!regime || !regime_is_harmonic(*regime))
    return "the simulated plate " +
           (!regime ? std::string("did not oscillate")
                    : "'" + std::string(regime_name(*regime)) + "'") +
           (evidence.empty() ? "" : ": " + evidence);
  return "the estimator measured no period";
}

std::string SimulatedPeriod::source() const {
  if (!period) return "";
  return from_trajectory ? "trajectory (the estimator accepted no period)" : "hall estimator";
}

SimulatedPeriod simulate_period(const Scene& scene) {
  const RunSummary summary = run_experiment(scene, RunOptions{});
  SimulatedPeriod s;
  s.period = summary.period ? summary.period : summary.period_trajectory;
  s.from_trajectory = !summary.period && summary.period_trajectory.has_value();
  if (summary.estimator && summary.estimator->periods_used > 0)
    s.period_std = summary.estimator->period_std;
  if (summary.estimator && !s.from_trajectory && summary.estimator->has_spread())
    s.period_std_error = summary.estimator->period_std_error;
  s.regime = summary.regime;
  s.evidence = summary.regime_evidence;
  s.failure = summary.failure;
  return s;
}

Scene scene_with_mu_k(const Scene& scene, double mu_k, std::optional<double> spacing) {
  Scene out = scene;
  out.friction.mu_k = mu_k;
  out.friction.from_paper = false;
  out.friction.paper_material.clear();
  out.friction.paper_period.reset();
  out.friction.paper_mu_k.reset();
  if (spacing) out.rollers.spacing = *spacing;
  const std::vector<SceneProblem> problems = check_scene(out);
  if (!problems.empty())
    throw std::runtime_error(problems.front().key + ": " + problems.front().message);
  return out;
}

}  // namespace fl
