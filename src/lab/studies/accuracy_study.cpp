#include "lab/studies/accuracy_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "core/analytic_model.hpp"
#include "core/integrator_error.hpp"
#include "core/oscillation_tracker.hpp"
#include "physics/rig_world.hpp"

namespace fl {

AccuracyStudy run_accuracy_study(const Scene& base, const AccuracyGrid& grid,
                                 const JobControl& control) {
  AccuracyStudy study;
  const CompiledRig rig = compile_rig(base);
  if (!rig.period_thick)
    throw DomainError("the accuracy study needs an oscillation: the scene has no restoring force");
  study.period_thick = *rig.period_thick;
  study.omega = *rig.omega;
  const double seconds = grid.periods * study.period_thick;
  for (const int iterations : grid.solver_iterations) {
    for (const double dt : grid.time_steps) {
      Scene scene = base;
      scene.world.time_step = dt;
      scene.world.solver_iterations = iterations;
      const auto start = std::chrono::steady_clock::now();
      RigWorld world(scene);
      OscillationTracker tracker;
      PlateState s = world.plate();
      tracker.add(0.0, s.x, s.vx);
      const long long steps = std::llround(seconds / dt);
      for (long long i = 0; i < steps; ++i) {
        if (i % 1000 == 0 && control.poll_stopping()) {
          study.interrupted = true;
          break;
        }
        world.step();
        s = world.plate();
        tracker.add(world.time(), s.x, s.vx);
      }
      if (study.interrupted) break;
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      AccuracyPoint p;
      p.time_step = dt;
      p.solver_iterations = iterations;
      p.wall_per_simulated_second = wall / world.time();
      p.predicted_error = integrator_period_bias(study.omega, dt);
      if (const auto fit = tracker.period()) {
        p.valid = true;
        p.period = fit->slope;
        p.period_error = p.period / study.period_thick - 1.0;
        p.amplitude_drift = tracker.amplitude_drift_per_period().value_or(0.0);
      }
      study.points.push_back(p);
    }
    if (study.interrupted) break;
  }
  study.law = fit_error_law(study.points, study.omega);
  return study;
}

std::optional<ErrorLaw> fit_error_law(const std::vector<AccuracyPoint>& points, double omega,
                                      double floor) {
  // At each step, the point with the most iterations: the integrator's error, not the solver's.
  std::map<double, const AccuracyPoint*> best;
  for (const AccuracyPoint& p : points) {
    if (!p.valid) continue;
    auto& slot = best[p.time_step];
    if (slot == nullptr || p.solver_iterations > slot->solver_iterations) slot = &p;
  }
  std::vector<double> x, y;
  for (const auto& [dt, p] : best) {
    if (p->period_error >= -floor) continue;  // the law is for a shortened period
    x.push_back(std::log(omega * dt));
    y.push_back(std::log(-p->period_error));
  }
  if (x.size() < 3) return std::nullopt;
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  ErrorLaw law;
  law.exponent = sxy / sxx;
  law.coefficient = std::exp(my - law.exponent * mx);
  law.points = static_cast<int>(x.size());
  return law;
}

}  // namespace fl
