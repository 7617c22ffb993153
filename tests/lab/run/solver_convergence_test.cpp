// The contact solver's convergence check (lab/run/solver_convergence.hpp): against a plate at rest
// on two rollers whose forces are known in closed form; silent on converged scenes; firing on a
// starved solver; the runs that start again at more iterations, and stop; the 200 mm plate on
// rollers 10 mm apart, which at the default iterations was once diagnosed "tips", oscillating
// with the thick-plate period; and docs/physics.md's tables of the solver at iterations held
// fixed, sliding (where the solver starts at the balance, physics/contact_warm_start.hpp) and
// stuck (where it starts from Bullet's own warm start and iterates to the balance).
#include "lab/run/solver_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "core/integrator_error.hpp"
#include "core/oscillation_tracker.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/run/experiment.hpp"
#include "physics/rig_world.hpp"
#include "scene/scene_yaml.hpp"
#include "support/close_rollers.hpp"

namespace fl {
namespace {

Scene scene_file(const std::string& name) {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  static const assets::PartCatalog parts =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/" + name, {},
      []() -> const PaperTable& { return table; },
      []() -> const assets::PartCatalog& { return parts; });
}

using test::close_rollers;
using test::stuck_on_close_rollers;

// A plate at rest at the centre on both rollers, level: the balance needs m g / 2 on each. A
// recorded split of m g / 2 +- d (with the velocities that split gives it through m and I) is
// off by exactly d; the even split is not off at all.
TEST(SolverConvergence, FindsTheSplitTheBalanceNeeds) {
  const CompiledRig rig = compile_rig(close_rollers());
  const double m = rig.plate.mass, I = rig.plate.inertia_pitch, g = rig.world.gravity;
  const double dt = rig.world.time_step, l = rig.rollers.spacing, h = rig.plate.h_c;
  PlateState rest;
  rest.z = h;
  std::array<RollerContact, 2> contacts{};
  for (int i = 0; i < 2; ++i) {
    contacts[i].touching = true;
    contacts[i].point_x = (i == 0 ? -0.5 : 0.5) * l;
    contacts[i].point_z = 0.0;
  }
  for (const double d : {0.0, 1e-3 * m * g, 0.05 * m * g}) {
    contacts[0].normal_force = 0.5 * m * g + d;
    contacts[1].normal_force = 0.5 * m * g - d;
    // Under these forces: no vertical acceleration, a pitch torque (l/2)(N0 - N1) = l d.
    PlateState after = rest;
    after.pitch_rate = l * d * dt / I;
    SolverConvergence check(rig);
    const auto r = check.observe(dt, rest, after, contacts);
    EXPECT_NEAR(check.worst_relative(), d / (m * g), 1e-9) << "d = " << d;
    ASSERT_EQ(r.has_value(), d / (m * g) > SolverConvergence::kTolerance);
    if (r) {
      EXPECT_NEAR(r->balanced[0], 0.5 * m * g, 1e-9 * m * g);
      EXPECT_NEAR(r->balanced[1], 0.5 * m * g, 1e-9 * m * g);
    }
  }
}

// Converged scenes: the check never fires, every step (the run keeps its iterations).
TEST(SolverConvergence, SilentOnTheShippedScenes) {
  for (const char* name : {"scenes/minimal.yaml", "scenes/paper-rig.yaml"}) {
    Scene scene = scene_file(name);
    scene.world.duration = 3.0;
    const RunSummary r = run_experiment(scene, {});
    EXPECT_FALSE(r.solver_iterations_raised.has_value())
        << name << ": " << *r.solver_iterations_raised;
    EXPECT_EQ(r.solver_iterations, scene.world.solver_iterations) << name;
    EXPECT_FALSE(r.failure.has_value()) << name;
  }
}

// A solver starved of iterations is caught at once: 1 iteration on the close rollers, as the
// plate sticks to a roller.
TEST(SolverConvergence, CatchesAStarvedSolver) {
  Scene scene = stuck_on_close_rollers();
  scene.world.solver_iterations = 1;
  const CompiledRig rig = compile_rig(scene);
  RigWorld world(rig);
  SolverConvergence check(rig);
  PlateState before = world.plate();
  std::optional<SolverResidual> fault;
  for (int i = 0; i < 100 && !fault; ++i) {
    world.step();
    fault = check.observe(world.time(), before, world.plate(), world.contacts());
    before = world.plate();
  }
  ASSERT_TRUE(fault.has_value());
  EXPECT_GT(fault->relative(), SolverConvergence::kTolerance);
}

// A run that shows its steps to an observer cannot start again: it stops with the numerical
// diagnosis, naming the setting to change.
TEST(SolverConvergence, StopsWithTheSettingToChangeWhenItCannotRestart) {
  Scene scene = stuck_on_close_rollers();
  RunOptions options;
  options.observer = [](const StepView&) {};
  const RunSummary r = run_experiment(scene, options);
  EXPECT_EQ(r.regime, Regime::kNumericallyFailed);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_NE(r.failure->find("world.solver_iterations"), std::string::npos) << *r.failure;
}

// A 600 mm plate stuck on the same rollers: e = (l/2)^2 / k^2 falls to 8e-4 and the split
// converges by only ((1 - e)/(1 + e))^2 = 0.9967 per iteration. The run doubles its iterations to
// the cap, 1280, still 0.01 % of the weight off, and stops naming both settings that can help.
TEST(SolverConvergence, StopsAtTheCapNamingIterationsAndStep) {
  Scene scene = stuck_on_close_rollers();
  scene.plate.length = 0.600;
  scene.world.duration = 0.2;
  const RunSummary r = run_experiment(scene, {});
  EXPECT_EQ(r.regime, Regime::kNumericallyFailed) << r.regime_evidence;
  EXPECT_EQ(r.solver_iterations, 1280);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_NE(r.failure->find("did not converge at 1280 iterations"), std::string::npos)
      << *r.failure;
  EXPECT_NE(r.failure->find("set world.solver_iterations above 1280 or a smaller world.time_step "
                            "(now 1 ms)"),
            std::string::npos)
      << *r.failure;
  ASSERT_TRUE(r.solver_iterations_raised.has_value());
  // Every doubling is listed, with the error it left.
  for (const char* n : {"10 (", "20 (", "40 (", "80 (", "160 (", "320 (", "640 (", "1280 ("})
    EXPECT_NE(r.solver_iterations_raised->find(n), std::string::npos) << n;
}

// After a pass that did not converge: double while doubling helps, up to the cap; stop naming
// the setting that can help when it does not (the step is then the limit), at the cap, or when
// a video has already shown the steps. (No scene tried reaches the "did not reduce" branch
// through a whole run, so its decision and text are checked here.)
TEST(SolverConvergence, EachWayOfStoppingNamesTheSettingThatCanHelp) {
  const std::string history = "10 (t = 0.001 s, a normal force 25 % of the weight off)";
  // The first pass, and a pass that reduced the error: double.
  EXPECT_EQ(solver_retry(10, 1280, 0.5, 0.0, false, history, 1e-3).iterations, 20);
  const SolverRetry doubled = solver_retry(640, 1280, 0.1, 0.3, false, history, 1e-3);
  EXPECT_EQ(doubled.iterations, 1280);
  EXPECT_EQ(doubled.advice, "");
  // The error did not fall: the step is the limit.
  for (const double error : {0.3, 0.4}) {
    const SolverRetry same = solver_retry(20, 1280, error, 0.3, false, history, 2e-3);
    EXPECT_FALSE(same.iterations.has_value()) << error;
    EXPECT_NE(same.advice.find("doubling the iterations did not reduce the error (" + history +
                               "): the step, not the solver, is the limit; set a smaller "
                               "world.time_step (now 2 ms)"),
              std::string::npos)
        << same.advice;
  }
  // At the cap.
  const SolverRetry cap = solver_retry(1280, 1280, 0.1, 0.3, false, history, 1e-3);
  EXPECT_FALSE(cap.iterations.has_value());
  EXPECT_NE(cap.advice.find("set world.solver_iterations above 1280 or a smaller world.time_step"),
            std::string::npos)
      << cap.advice;
  // A video: never again, whatever the error did.
  const SolverRetry video = solver_retry(10, 1280, 0.5, 0.0, true, history, 1e-3);
  EXPECT_FALSE(video.iterations.has_value());
  EXPECT_NE(video.advice.find("set world.solver_iterations to 20 or more"), std::string::npos)
      << video.advice;
}

// The 200 mm plate on rollers 10 mm apart at the default 10 iterations. Started from zero or from
// 85 % of the last step's impulses, Bullet's solver needed 640 iterations here (the run raised
// them itself); started at the balance it converges at the scene's own 10 and oscillates with the
// thick-plate period, within the integrator's predicted bias (plus the trajectory fit's own
// standard error, three of them).
TEST(SolverConvergence, CloseRollersOscillateWithTheThickPeriod) {
  const Scene scene = close_rollers();
  ASSERT_EQ(scene.world.solver_iterations, 10);
  const RunSummary r = run_experiment(scene, {});
  ASSERT_EQ(r.regime, Regime::kOscillates) << r.regime_evidence;
  EXPECT_EQ(r.solver_iterations, 10);
  EXPECT_FALSE(r.solver_iterations_raised.has_value()) << *r.solver_iterations_raised;
  ASSERT_TRUE(r.period_trajectory && r.period_thick && r.predicted_integrator_bias);
  // The run against the thick formula written out, T = pi sqrt(2 (l - 2 mu_k h_c) / (mu_k g)),
  // not against the lab's own value of it.
  const double l = r.spacing, mu = r.mu_k_set, g = r.gravity;
  const double thick = std::numbers::pi * std::sqrt(2.0 * (l - 2.0 * mu * r.h_c) / (mu * g));
  const double error = *r.period_trajectory / thick - 1.0;
  EXPECT_NEAR(error, *r.predicted_integrator_bias,
              std::fabs(*r.predicted_integrator_bias) +
                  3.0 * *r.period_trajectory_err / *r.period_trajectory);
}

// A run that raised its iterations (the plate stuck on the close rollers) is exactly a run of the
// scene at the iterations it ended with.
TEST(SolverConvergence, ARaisedRunIsTheRunAtItsLastIterations) {
  const Scene scene = stuck_on_close_rollers();
  const RunSummary r = run_experiment(scene, {});
  EXPECT_GT(r.solver_iterations, 10);
  ASSERT_TRUE(r.solver_iterations_raised.has_value());
  ASSERT_FALSE(r.failure.has_value()) << *r.failure;
  Scene raised = scene;
  raised.world.solver_iterations = r.solver_iterations;
  const RunSummary again = run_experiment(raised, {});
  EXPECT_FALSE(again.solver_iterations_raised.has_value());
  EXPECT_EQ(again.regime, r.regime);
  ASSERT_TRUE(r.period_trajectory && again.period_trajectory);
  EXPECT_EQ(*again.period_trajectory, *r.period_trajectory);
}

// docs/physics.md's tables of the solver on these close rollers, at iterations held fixed (a run
// raises them itself, so the tables are only reproducible by stepping the world directly): the
// load split's error over the steps, and the period's error against the thick formula.
struct FixedIterations {
  double typical = 0.0;       // median over the steps on both rollers of the split's error / m g
  double worst = 0.0;         // the largest
  double period_error = 0.0;  // the trajectory's period against the thick formula, relative
  double bias = 0.0;          // the integrator's predicted -(omega dt)^2 / 24
};

FixedIterations step_at(Scene scene, int iterations) {
  scene.world.solver_iterations = iterations;
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
  const double thick =
      period_thick(rig.rollers.spacing, rig.friction.mu_k, rig.plate.h_c, rig.world.gravity);
  if (const auto p = tracker.period()) out.period_error = p->slope / thick - 1.0;
  out.bias = integrator_period_bias(2.0 * std::numbers::pi / thick, scene.world.time_step);
  return out;
}

// Both contacts sliding: the solver starts at the balance, and whatever the iterations, even one,
// every step's split is the balance to rounding (Bullet's own start needed 640 iterations for
// 1e-9) and the period's error is the integrator's bias (within the trajectory fit's scatter,
// 2e-9 here).
TEST(SolverTable, SlidingContactsAreBalancedAtAnyIterations) {
  for (const int n : {1, 2, 10, 40}) {
    const FixedIterations r = step_at(close_rollers(), n);
    SCOPED_TRACE(n);
    std::printf("%4d iterations: typical %.2e, worst %.2e, period error %.4e (bias %.4e)\n", n,
                r.typical, r.worst, r.period_error, r.bias);
    EXPECT_GT(r.worst, 0.0);  // the check saw the plate on both rollers
    EXPECT_LT(r.worst, 1e-9);
    EXPECT_NEAR(r.period_error, r.bias, 0.02 * std::fabs(r.bias));
  }
}

// A stuck contact: the solver iterates from Bullet's start, and the worst step's split error (at
// the moment of sticking) shrinks with every doubling until it is below the run's tolerance, at
// 320 (the run's own choice); the steps where both contacts slide stay at rounding throughout.
TEST(SolverTable, AStuckContactsSplitConvergesWithTheIterations) {
  double worst = 1.0;
  for (const int n : {10, 20, 40, 80, 160, 320, 640}) {
    const FixedIterations r = step_at(stuck_on_close_rollers(), n);
    SCOPED_TRACE(n);
    std::printf("%4d iterations: typical %.2e, worst %.2e\n", n, r.typical, r.worst);
    EXPECT_LT(r.worst, worst);
    EXPECT_LT(r.typical, 1e-12);
    EXPECT_EQ(r.worst < SolverConvergence::kTolerance, n >= 320);
    worst = r.worst;
  }
}

}  // namespace
}  // namespace fl
