// Rollers at different speeds (rollers.speed: [roller 0, roller 1]). With coulomb friction nothing
// changes while both slip: the friction's size does not depend on the slip. With a slip-speed law
// each roller pulls with its own mu at its own slip, and the plate oscillates about
// x_eq = (l/2) (mu_0 - mu_1) / (mu_0 + mu_1) (at rest, whatever h_c; core/tilted_rig.hpp). The
// Bullet world is checked against an independent model written here: the plate as one degree of
// freedom on rigid contacts, the normal forces from the balance of forces and torques about the
// centre of mass (the friction's torque h_c (F_0 + F_1) included), integrated by RK4 at 10 us;
// its period within 0.1 % and its centre within 0.05 mm, both read from the turning points in the
// same way.
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

struct Oscillation {
  double period = 0.0;  // s, mean time between successive maxima
  double centre = 0.0;  // m, mean of the midpoints of successive turning points
};

// The plate on rollers turning inward at surface speeds u0 (roller 0, toward +x) and u1 (roller
// 1, toward -x), under mu(s) = mu_k + beta s, from x0 at rest; read over the turning points at
// or after `since`.
Oscillation independent_model(double l, double h_c, double mu_k, double beta, double u0,
                              const std::function<double(double)>& u1_at, double x0,
                              double duration, double since) {
  const double g = 9.81;
  const auto mu = [&](double slip) { return mu_k + beta * std::fabs(slip); };
  double u1 = u1_at(0.0);
  const auto acceleration = [&](double x, double v) {
    const double a0 = std::copysign(mu(u0 - v), u0 - v);   // roller 0's pull on the plate, / N0
    const double a1 = -std::copysign(mu(v + u1), v + u1);  // roller 1's, / N1
    // N0 + N1 = W and (l/2 + x) N0 - (l/2 - x) N1 = h_c (a0 N0 + a1 N1).
    const double n0 = (0.5 * l - x + h_c * a1) / (l + h_c * (a1 - a0));
    return g * (a0 * n0 + a1 * (1.0 - n0));
  };
  const double dt = 1e-5;
  double x = x0, v = 0.0, t = 0.0;
  std::vector<double> turn_t, turn_x, maxima;
  while (t < duration) {
    u1 = u1_at(t);
    const double k1x = v, k1v = acceleration(x, v);
    u1 = u1_at(t + 0.5 * dt);
    const double k2x = v + 0.5 * dt * k1v, k2v = acceleration(x + 0.5 * dt * k1x, k2x);
    const double k3x = v + 0.5 * dt * k2v, k3v = acceleration(x + 0.5 * dt * k2x, k3x);
    u1 = u1_at(t + dt);
    const double k4x = v + dt * k3v, k4v = acceleration(x + dt * k3x, k4x);
    const double x1 = x + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v1 = v + dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if ((v > 0.0 && v1 <= 0.0) || (v < 0.0 && v1 >= 0.0)) {
      // The turning point within the step, by a parabola through the velocity's root.
      const double f = v / (v - v1);
      const double at = t + f * dt;
      turn_t.push_back(at);
      turn_x.push_back(x + v * f * dt * 0.5 + (x1 - x - v * dt * 0.5) * f * f);
      if (v > 0.0) maxima.push_back(at);
    }
    x = x1;
    v = v1;
    t += dt;
  }
  Oscillation out;
  int pairs = 0;
  for (std::size_t k = 1; k < turn_t.size(); ++k) {
    if (turn_t[k - 1] < since) continue;
    out.centre += 0.5 * (turn_x[k - 1] + turn_x[k]);
    ++pairs;
  }
  out.centre = pairs > 0 ? out.centre / pairs : std::nan("");
  std::vector<double> late;
  for (double m : maxima)
    if (m >= since) late.push_back(m);
  const std::size_t n = late.size();
  out.period = n >= 2 ? (late[n - 1] - late[0]) / static_cast<double>(n - 1) : std::nan("");
  return out;
}

RunSummary run(const std::string& speeds, const std::string& beta, double* h_c) {
  std::vector<SceneOverride> keys{
      {"rollers.speed", speeds}, {"plate.offset", "20 mm"}, {"world.duration", "20 s"}};
  if (!beta.empty()) {
    keys.push_back({"friction.law", "stribeck"});
    keys.push_back({"friction.beta", beta});
  }
  const CompiledRig rig = compile_rig(test::minimal_without_sensor(keys));
  *h_c = rig.plate.h_c;
  return run_experiment(rig, {});
}

TEST(UnequalRollers, CoulombFrictionDoesNotCareWhileBothSlip) {
  double h_c = 0.0;
  const RunSummary r = run("[1600 rpm, 800 rpm]", "", &h_c);
  ASSERT_EQ(r.regime, Regime::kOscillates) << r.regime_evidence;
  ASSERT_TRUE(r.period_trajectory && r.period_thick && r.oscillation_centre);
  EXPECT_NEAR(*r.period_trajectory / *r.period_thick, 1.0, 1e-4);
  EXPECT_NEAR(*r.oscillation_centre, 0.0, 0.05e-3);
}

TEST(UnequalRollers, ASlipSpeedLawMovesTheCentreAsAnIndependentModelDoes) {
  const double rpm = 2.0 * std::numbers::pi / 60.0, a = 0.010, l = 0.089, mu_k = 0.29;
  for (const char* beta : {"0.02 s/m", "-0.004 s/m"}) {
    for (const auto& [slow, speeds] :
         {std::pair{800.0, "[1600 rpm, 800 rpm]"}, std::pair{1200.0, "[1600 rpm, 1200 rpm]"}}) {
      double h_c = 0.0;
      const RunSummary r = run(speeds, beta, &h_c);
      const std::string where = fmt::format("beta {}, {}: {}", beta, speeds, r.regime_evidence);
      ASSERT_TRUE(r.period_trajectory && r.oscillation_centre && r.oscillation_centre_theory)
          << where;
      const double u1 = slow * rpm * a;
      const Oscillation model = independent_model(
          l, h_c, mu_k, std::stod(beta), 1600 * rpm * a, [u1](double) { return u1; }, 0.020, 20.0,
          r.regime_since);
      EXPECT_NEAR(*r.period_trajectory / model.period, 1.0, 1e-3) << where;
      EXPECT_NEAR(*r.oscillation_centre, model.centre, 0.05e-3) << where;
      // Theory's centre at rest, (l/2) (mu_0 - mu_1) / (mu_0 + mu_1).
      const double mu_0 = mu_k + std::stod(beta) * 1600 * rpm * a;
      const double mu_1 = mu_k + std::stod(beta) * slow * rpm * a;
      const double at_rest = 0.5 * l * (mu_0 - mu_1) / (mu_0 + mu_1);
      EXPECT_NEAR(*r.oscillation_centre_theory, at_rest, 1e-12) << where;
      // The centre did move, by about theory's at rest (the check above is not met by 0 = 0).
      EXPECT_GT(std::fabs(model.centre), 0.5 * std::fabs(at_rest)) << where;
    }
  }
}

// A ramp with a speed for each roller: roller 1 slows from 1600 to 800 rpm over the first 10 s
// while roller 0 holds 1600 rpm, under a slip-speed law. The plate follows the independent model
// driven by the same schedule (its centre moves as roller 1 slows), and the summary gives each
// roller's mean speed over the run: 1600 rpm, and (1600 + 800) / 2 for 10 s then 800 for 10 s,
// 1000 rpm.
TEST(UnequalRollers, ARampWithASpeedForEachRollerDrivesEachRoller) {
  const double rpm = 2.0 * std::numbers::pi / 60.0, a = 0.010, l = 0.089, mu_k = 0.29;
  const std::vector<SceneOverride> keys{
      {"rollers.speed_ramp",
       "[{at: 0 s, speed: [1600 rpm, 1600 rpm]}, {at: 10 s, speed: [1600 rpm, 800 rpm]}]"},
      {"plate.offset", "20 mm"},
      {"world.duration", "20 s"},
      {"friction.law", "stribeck"},
      {"friction.beta", "0.02 s/m"}};
  // The ramped scene (scenes/roller-ramp.yaml: the minimal rig without a sensor) with this ramp.
  const CompiledRig rig = compile_rig(test::scene_file("roller-ramp.yaml", keys));
  ASSERT_EQ(rig.friction.mu_k, mu_k);
  const RunSummary r = run_experiment(rig, {});
  ASSERT_TRUE(r.period_trajectory && r.oscillation_centre) << r.regime_evidence;
  EXPECT_NEAR(r.roller_speed / rpm, 1600.0, 1e-9);
  // The mean of the steps' speeds: the ramp's mean to within one step's share of it.
  EXPECT_NEAR(r.roller_speed_1 / rpm, 1000.0, 800.0 * rig.world.time_step / 20.0 + 1e-9);
  const auto u1 = [&](double t) { return (t < 10.0 ? 1600.0 - 80.0 * t : 800.0) * rpm * a; };
  const Oscillation model = independent_model(l, rig.plate.h_c, mu_k, 0.02, 1600 * rpm * a, u1,
                                              0.020, 20.0, r.regime_since);
  EXPECT_NEAR(*r.period_trajectory / model.period, 1.0, 1e-3);
  EXPECT_NEAR(*r.oscillation_centre, model.centre, 0.05e-3);
  // Roller 1 at 800 rpm for the last half: the centre well off the midpoint (theory's at rest at
  // the end's speeds is -1.5 mm), not where equal speeds would hold it.
  EXPECT_GT(std::fabs(model.centre), 0.5e-3);
}

}  // namespace
}  // namespace fl
