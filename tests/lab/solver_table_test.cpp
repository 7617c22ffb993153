// docs/physics.md's table of the contact solver on the 200 mm plate on rollers 10 mm apart, at
// iterations held fixed (a run raises them itself, so the table is only reproducible by stepping
// the world directly): the load split's error shrinks with every doubling, and the period's
// error against the thick formula approaches the integrator's own bias -(omega dt)^2 / 24 as the
// split converges, in proportion to the typical step's split error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "core/integrator_error.hpp"
#include "core/oscillation_tracker.hpp"
#include "lab/solver_convergence.hpp"
#include "physics/rig_world.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {
namespace {

// The minimal plate on rollers 10 mm apart, released 2 mm off centre (as solver_convergence_test).
Scene close_rollers(int iterations) {
  Scene s;
  s.friction.mu_k = 0.29;
  s.rollers.spacing = 0.010;
  s.rollers.radius = 0.004;
  s.plate.offset = 0.002;
  s.world.duration = 3.0;
  s.world.solver_iterations = iterations;
  return s;
}

struct FixedIterations {
  double typical = 0.0;       // median over the steps on both rollers of the split's error / m g
  double worst = 0.0;         // the largest
  double period_error = 0.0;  // the trajectory's period against the thick formula, relative
  double bias = 0.0;          // the integrator's predicted -(omega dt)^2 / 24
};

FixedIterations step_at(int iterations) {
  const Scene scene = close_rollers(iterations);
  const CompiledRig rig = compile_rig(scene);
  RigWorld world(rig);
  OscillationTracker tracker;
  std::vector<double> errors;
  PlateState before = world.plate();
  const long long steps = std::llround(scene.world.duration / scene.world.time_step);
  for (long long i = 0; i < steps; ++i) {
    world.step();
    const PlateState after = world.plate();
    // A fresh check per step: its worst error is this step's own.
    SolverConvergence check(rig);
    check.observe(world.time(), before, after, world.contacts());
    if (check.worst_relative() > 0.0) errors.push_back(check.worst_relative());
    tracker.add(world.time(), after.x, after.vx);
    before = after;
  }
  FixedIterations out;
  if (errors.empty()) return out;
  std::sort(errors.begin(), errors.end());
  out.typical = errors[errors.size() / 2];
  out.worst = errors.back();
  const double thick = period_thick(rig.spacing, rig.mu_k, rig.plate.h_c, rig.gravity);
  if (const auto p = tracker.period()) out.period_error = p->slope / thick - 1.0;
  out.bias = integrator_period_bias(2.0 * std::numbers::pi / thick, scene.world.time_step);
  return out;
}

TEST(SolverTable, TheSplitConvergesWithTheIterationsAndThePeriodWithIt) {
  const FixedIterations ten = step_at(10);
  // At 10 iterations a step's split is off by most of the weight (0.79 at the release).
  EXPECT_GT(ten.worst, 0.5);
  double typical = ten.typical, off_bias = 1.0;
  for (const int n : {20, 40, 80, 160, 320, 640}) {
    const FixedIterations r = step_at(n);
    SCOPED_TRACE(n);
    std::printf("%4d iterations: typical %.2e, worst %.2e, period error %.4e (bias %.4e)\n", n,
                r.typical, r.worst, r.period_error, r.bias);
    // Every doubling leaves a smaller typical error.
    EXPECT_LT(r.typical, typical);
    typical = r.typical;
    // The period's error beyond the integrator's bias shrinks with it ...
    const double beyond = std::fabs(r.period_error - r.bias);
    if (n <= 160) {
      EXPECT_LT(beyond, off_bias);
      // ... in proportion to the typical split error (6.2e-4 to 7.0e-4 of it in the table).
      EXPECT_GT(beyond / r.typical, 5e-4);
      EXPECT_LT(beyond / r.typical, 8e-4);
    }
    off_bias = beyond;
    if (n == 640) {
      // Converged: the split is off by rounding-sized amounts and the period is the bias.
      EXPECT_LT(r.worst, 1e-6);
      EXPECT_LT(r.typical, SolverConvergence::kTolerance * 1e-3);
      EXPECT_NEAR(r.period_error, r.bias, 0.02 * std::fabs(r.bias));
    }
  }
}

}  // namespace
}  // namespace fl
