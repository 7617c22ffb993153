// A whole run: the period the rig's estimator measures from the simulated Hall signal against
// the thick-plate formula (the claim: within 0.05 %), the parts built only when named,
// determinism of every output, and the choice of a step from an accuracy target.
#include "lab/run/experiment.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab/run/step_choice.hpp"
#include "lab/studies/accuracy_study.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kEstimatorTolerance = 5e-4;  // 0.05 %

Scene minimal_scene(std::vector<SceneOverride> overrides = {}) {
  return test::scene_file("minimal.yaml", overrides);
}

struct MaterialCase {
  const char* material;
  const char* temperature;
};

class EstimatorPeriod : public ::testing::TestWithParam<MaterialCase> {};

TEST_P(EstimatorPeriod, WithinFiveHundredthsOfAPercentOfTheThickFormula) {
  Scene s = minimal_scene(
      {{"friction.mu_k", GetParam().material}, {"friction.temperature", GetParam().temperature}});
  // At least 12 periods, so the estimator sees the geometry and averages enough.
  s.world.duration = std::max(10.0, 12.0 * period_thin(s.rollers.spacing, s.friction.mu_k));
  const RunSummary r = run_experiment(s, {});
  ASSERT_TRUE(r.estimator.has_value());
  ASSERT_GE(r.estimator->periods_used, 8);
  EXPECT_EQ(r.estimator->periods_discarded, 0);
  ASSERT_TRUE(r.period_thick.has_value());
  EXPECT_NEAR(r.estimator->period / *r.period_thick - 1.0, 0.0, kEstimatorTolerance)
      << GetParam().material << " " << GetParam().temperature;
  EXPECT_EQ(r.regime, Regime::kOscillates);
}

INSTANTIATE_TEST_SUITE_P(TableI, EstimatorPeriod,
                         ::testing::Values(MaterialCase{"lego", "300 K"},
                                           MaterialCase{"iron", "300 K"},
                                           MaterialCase{"cardboard", "300 K"},
                                           MaterialCase{"plexiglas", "77 K"},
                                           MaterialCase{"construction-wood", "77 K"}),
                         [](const auto& param_info) {
                           std::string name = std::string(param_info.param.material) + "_" +
                                              param_info.param.temperature;
                           for (char& c : name)
                             if (c == '-' || c == ' ') c = '_';
                           return name;
                         });

TEST(Experiment, AScenewithoutSensorBuildsNoEstimator) {
  Scene s = minimal_scene();
  s.sensor.reset();
  s.world.duration = 3.0;
  const RunSummary r = run_experiment(s, {});
  EXPECT_FALSE(r.estimator.has_value());
  ASSERT_TRUE(r.period_trajectory.has_value());
  EXPECT_NEAR(*r.period_trajectory / *r.period_thick - 1.0, 0.0, 1e-4);
}

TEST(Experiment, SameSceneAndSeedGiveBitIdenticalOutputs) {
  Scene s = minimal_scene();
  s.world.duration = 3.0;
  RunOptions options;
  options.record_trajectory = true;
  options.record_hall = true;
  RunRecording a, b;
  const RunSummary ra = run_experiment(s, options, &a);
  const RunSummary rb = run_experiment(s, options, &b);
  EXPECT_EQ(trajectory_csv(a), trajectory_csv(b));
  EXPECT_EQ(hall_csv(a), hall_csv(b));
  EXPECT_EQ(summary_json(ra).dump(), summary_json(rb).dump());
  // Another seed changes the sensor's noise, not the physics.
  s.world.seed = 2;
  RunRecording c;
  run_experiment(s, options, &c);
  EXPECT_EQ(trajectory_csv(a), trajectory_csv(c));
  EXPECT_NE(hall_csv(a), hall_csv(c));
}

// A run of the scene for 2 s that records its Hall samples.
RunRecording hall_for_two_seconds(Scene s) {
  s.world.duration = 2.0;
  RunRecording rec;
  RunOptions hall_only;
  hall_only.record_hall = true;
  run_experiment(s, hall_only, &rec);
  return rec;
}

TEST(Experiment, HallCsvHasOneSamplePerClockTick) {
  const RunRecording rec = hall_for_two_seconds(minimal_scene());
  ASSERT_EQ(rec.hall.size(), 2001u);
  EXPECT_EQ(rec.hall.back().t_us, 2000000u);
  EXPECT_EQ(hall_csv(rec).substr(0, 9), "t_us,adc\n");
}

// A board clock running 0.5 % fast (sensor.clock_error): it samples and stamps by its own time,
// so the estimator's period reads 1.005 times the trajectory's (the true one) and its mu_k
// 1.005^-2 times the unbiased one; over 2 s the board stamps 2.01 s of samples.
TEST(Experiment, AFastBoardClockLengthensEveryPeriodByItsError) {
  Scene s = minimal_scene({{"sensor.clock_error", "0.5 %"}});
  s.world.duration = 10.0;
  const RunSummary r = run_experiment(s, {});
  ASSERT_TRUE(r.estimator && r.estimator->periods_used >= 8 && r.period_trajectory);
  ASSERT_TRUE(r.clock_error.has_value());
  EXPECT_NEAR(r.estimator->period / *r.period_trajectory, 1.005, kEstimatorTolerance);
  const RunSummary exact = run_experiment(minimal_scene({{"world.duration", "10 s"}}), {});
  ASSERT_TRUE(exact.estimator && exact.estimator->periods_used >= 8);
  EXPECT_NEAR(r.estimator->mu_k / exact.estimator->mu_k, 1.0 / (1.005 * 1.005), 2e-3);
  EXPECT_FALSE(exact.clock_error.has_value());

  const RunRecording rec = hall_for_two_seconds(s);
  // Samples whose board time falls within 2 s of true time: up to 2.01 s by the board's clock.
  ASSERT_EQ(rec.hall.size(), 2011u);
  EXPECT_EQ(rec.hall.back().t_us, 2010000u);
}

TEST(StepChoice, TheChosenStepMeetsTheTargetAndTheNextLargerDoesNot) {
  // The trajectory's period alone: no sensor's error to leave room for.
  Scene s = minimal_scene();
  s.sensor.reset();
  for (double target : {1e-3, 1e-4, 1e-5}) {
    Scene at = s;
    const StepChoice choice = step_for_accuracy(s, target);
    EXPECT_EQ(choice.basis, StepBasis::kIntegratorBias);
    at.world.time_step = choice.time_step;
    // The bias takes its share of the target, and one step coarser would take more.
    const double share = kIntegratorShareOfAccuracy * target;
    EXPECT_LE(std::fabs(predicted_integrator_bias(at)), share);
    Scene coarser = at;
    coarser.world.time_step = 1.0 / (1.0 / at.world.time_step - 1.0);
    EXPECT_GT(std::fabs(predicted_integrator_bias(coarser)), share);
    // And the simulation at that step meets the target.
    at.world.duration = 8.0;
    at.sensor.reset();
    const RunSummary r = run_experiment(at, {});
    EXPECT_LE(std::fabs(*r.period_trajectory / *r.period_thick - 1.0), target) << target;
  }
}

// A rig with a Hall sensor reports the estimator's period, which carries the sensor's timing error
// whatever the step (sensor/hall_timing.hpp): the step's bias takes what that leaves of the
// target, and a target the sensor alone cannot meet is refused, saying the run that would.
TEST(StepChoice, AHallSensorsErrorTakesItsShareOfTheTarget) {
  Scene s = minimal_scene({{"world.duration", "20 s"}});
  const StepChoice choice = step_for_accuracy(s, 1e-4);
  ASSERT_TRUE(choice.sensor_error.has_value());
  EXPECT_GT(*choice.sensor_error, 0.0);
  EXPECT_LT(*choice.sensor_error, kSensorShareOfAccuracy * 1e-4);
  Scene at = s;
  at.world.time_step = choice.time_step;
  const double share = kIntegratorShareOfAccuracy * 1e-4 - *choice.sensor_error;
  EXPECT_LE(std::fabs(predicted_integrator_bias(at)), share);
  Scene coarser = at;
  coarser.world.time_step = 1.0 / (1.0 / at.world.time_step - 1.0);
  EXPECT_GT(std::fabs(predicted_integrator_bias(coarser)), share);
  // Ten times tighter: 20 s of periods cannot time the plate that finely.
  std::string message;
  try {
    step_for_accuracy(s, 1e-5);
  } catch (const DomainError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the rig's estimator times each turning point to +-"), std::string::npos)
      << message;
  // (No std::regex: GCC 12's libstdc++ regex trips -Wmaybe-uninitialized under the sanitizers.)
  const std::string advice = "ask for a \u27e6duration\u27e7 of at least ";
  const std::size_t found = message.find(advice);
  ASSERT_NE(found, std::string::npos) << message;
  // The run it names meets it, and one a tenth shorter does not.
  s.world.duration = std::stod(message.substr(found + advice.size()));
  EXPECT_NO_THROW(step_for_accuracy(s, 1e-5));
  s.world.duration *= 0.9;
  EXPECT_THROW(step_for_accuracy(s, 1e-5), DomainError);
}

// A law whose Stribeck drop is narrower than the bias's step, on rollers slow enough that the
// plate sticks: the step resolves the drop (v_s / (mu_s g)), and the run at it is a stick-slip
// run, not a numerical failure.
TEST(StepChoice, AStickingPlateOnANarrowStribeckDropGetsTheStepThatResolvesIt) {
  Scene s = minimal_scene();
  s.friction.law = FrictionLawKind::kStribeck;
  s.friction.mu_k = 0.29;
  s.friction.mu_s = 0.35;
  s.friction.v_s = 1e-3;
  s.rollers.speed = 100.0 * 2.0 * std::numbers::pi / 60.0;
  const StepChoice choice = step_for_accuracy(s, 1e-4);
  EXPECT_EQ(choice.basis, StepBasis::kFrictionLaw) << choice.reason;
  const double drop_step = *s.friction.v_s / (*s.friction.mu_s * s.world.gravity);
  EXPECT_LE(choice.time_step, drop_step);
  EXPECT_GT(1.0 / (1.0 / choice.time_step - 1.0), drop_step);
  Scene at = s;
  at.world.time_step = choice.time_step;
  at.world.duration = 3.0;
  at.sensor.reset();
  const RunSummary r = run_experiment(at, {});
  EXPECT_EQ(r.regime, Regime::kStickSlip) << r.regime_evidence;
  // The same rollers at full speed: the plate never sticks, and the bias alone sizes the step.
  s.rollers.speed = 1600.0 * 2.0 * std::numbers::pi / 60.0;
  EXPECT_EQ(step_for_accuracy(s, 1e-4).basis, StepBasis::kIntegratorBias);
}

// No oscillation (l <= 2 mu_k h_c) has no period to size a step by: a run refuses the accuracy,
// a sweep point keeps its scene's step and says it is a fallback.
TEST(StepChoice, NoOscillationKeepsTheScenesStepAndSaysSo) {
  Scene s = minimal_scene();
  s.friction.mu_k = 10.0;
  s.friction.from_paper = false;
  s.rollers.spacing = 0.04;
  EXPECT_THROW(step_for_accuracy(s, 1e-4), DomainError);
  const StepChoice choice = step_for_accuracy_or_scene(compile_rig(s), 1e-4);
  EXPECT_EQ(choice.basis, StepBasis::kSceneStep);
  EXPECT_EQ(choice.time_step, s.world.time_step);
  EXPECT_NE(step_basis_name(choice.basis).find("fallback"), std::string::npos);
}

TEST(ErrorLaw, FitRecoversAKnownLaw) {
  std::vector<AccuracyPoint> points;
  const double omega = 8.0;
  for (double dt : {1e-2, 5e-3, 2e-3, 1e-3}) {
    AccuracyPoint p;
    p.valid = true;
    p.time_step = dt;
    p.solver_iterations = 10;
    p.period_error = -0.05 * std::pow(omega * dt, 2.2);
    points.push_back(p);
  }
  const auto law = fit_error_law(points, omega);
  ASSERT_TRUE(law.has_value());
  EXPECT_NEAR(law->exponent, 2.2, 1e-12);
  EXPECT_NEAR(law->coefficient, 0.05, 1e-12);
}

}  // namespace
}  // namespace fl
