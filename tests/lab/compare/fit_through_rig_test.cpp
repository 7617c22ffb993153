// fit --through-rig against a series the rig itself measured: the minimal scene simulated at a
// known mu_k at five spacings (its estimator's periods) is refitted through the same scene, and
// must give that mu_k back within its error, and the scene's own h_c. At a coarse step (1/60 s)
// the integrator's phase error, -(omega dt)^2 / 24 of T, shifts every T^2 by the same
// -(2 pi dt)^2 / 12 (docs/physics.md): the closed form reads it as a larger h_c, many standard
// errors off the plate's; through the rig the plate's h_c comes back.
#include "lab/compare/fit_through_rig.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/compare/simulated_period.hpp"
#include "scene/scene.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

constexpr double kMuK = 0.29;

// The series the scene measures at mu_k: each row run as fit_through_rig runs it (15 periods),
// with dT chosen above the estimator's own scatter between spacings (about 2e-5 of T, 0.02 ms).
std::vector<SpacingPeriod> measured_by(const Scene& scene, double period_err) {
  std::vector<SpacingPeriod> series;
  for (const double l : {0.070, 0.080, 0.090, 0.100, 0.110}) {
    Scene row = scene_with_mu_k(scene, kMuK, l);
    row.world.duration = std::max(scene.world.duration, 15.0 * period_thin(l, kMuK));
    const SimulatedPeriod s = simulate_period(row);
    EXPECT_TRUE(s.oscillates()) << l;
    series.push_back({l, *s.period, period_err, std::nullopt});
  }
  return series;
}

TEST(FitThroughRig, TheMinimalScenesOwnSeriesGivesItsMuKBack) {
  const Scene scene = test::scene_file("minimal.yaml");
  const std::vector<SpacingPeriod> series = measured_by(scene, 0.05e-3);
  const FitThroughRig fit =
      fit_through_rig(series, {.scene = scene, .gravity = scene.world.gravity});
  ASSERT_TRUE(fit.fit.mu_k);
  EXPECT_TRUE(fit.converged);
  EXPECT_LT(std::fabs(*fit.fit.mu_k - kMuK), *fit.fit.mu_k_err)
      << *fit.fit.mu_k << " +- " << *fit.fit.mu_k_err;
  EXPECT_LT(std::fabs(*fit.fit.h_c - fit.h_c_scene), *fit.fit.h_c_err);
  EXPECT_EQ(fit.simulations, fit.iterations * 5);
  EXPECT_EQ(fit.mu_k_path.size(), static_cast<std::size_t>(fit.iterations) + 1);
  for (const FitThroughRigRow& row : fit.rows) {
    EXPECT_EQ(row.period_simulated_source, "hall estimator");
    // At 1 ms the rig and the closed form agree to the estimator's scatter (docs/physics.md).
    EXPECT_NEAR(row.correction, 1.0, 1e-4);
  }
  std::printf("1 ms: mu_k %.6f +- %.6f (closed form %.6f), h_c %.4f +- %.4f mm (scene %.4f)\n",
              *fit.fit.mu_k, *fit.fit.mu_k_err, *fit.closed_form.mu_k, *fit.fit.h_c * 1e3,
              *fit.fit.h_c_err * 1e3, fit.h_c_scene * 1e3);
}

TEST(FitThroughRig, ACoarseStepsPhaseErrorIsTakenOutOfHc) {
  Scene scene = test::scene_file("minimal.yaml");
  scene.world.time_step = 1.0 / 60.0;
  const std::vector<SpacingPeriod> series = measured_by(scene, 0.05e-3);
  const FitThroughRig fit =
      fit_through_rig(series, {.scene = scene, .gravity = scene.world.gravity});
  ASSERT_TRUE(fit.fit.mu_k && fit.closed_form.h_c);
  EXPECT_LT(std::fabs(*fit.fit.mu_k - kMuK), *fit.fit.mu_k_err);
  EXPECT_LT(std::fabs(*fit.fit.h_c - fit.h_c_scene), *fit.fit.h_c_err);
  // The closed form's h_c is high by (2 pi dt)^2 / 12 g / (4 pi^2) = g dt^2 / 12 = 0.227 mm, more
  // than 3 of its standard errors (0.05 ms on T gives about 0.05 mm on h_c).
  const double shift = scene.world.gravity * scene.world.time_step * scene.world.time_step / 12.0;
  EXPECT_GT(*fit.closed_form.h_c - fit.h_c_scene, 3.0 * *fit.closed_form.h_c_err);
  EXPECT_NEAR(*fit.closed_form.h_c - fit.h_c_scene, shift, 3.0 * *fit.closed_form.h_c_err);
  std::printf(
      "1/60 s: mu_k %.6f +- %.6f (closed form %.6f), h_c %.4f +- %.4f mm (closed form "
      "%.4f, scene %.4f, predicted shift %.4f)\n",
      *fit.fit.mu_k, *fit.fit.mu_k_err, *fit.closed_form.mu_k, *fit.fit.h_c * 1e3,
      *fit.fit.h_c_err * 1e3, *fit.closed_form.h_c * 1e3, fit.h_c_scene * 1e3, shift * 1e3);
}

TEST(FitThroughRig, ARowWhoseRunGivesNoPeriodIsRefusedWithTheReason) {
  const Scene scene = test::scene_file("minimal.yaml");
  // At l = 30 mm the plate released 20 mm off centre is past its tipping amplitude
  // l/2 - mu_k h_c = 14.3 mm: it tips off the rollers, and there is no period to correct with.
  const double h_c = 0.00258;
  const std::vector<SpacingPeriod> series{{0.030, period_thick(0.030, kMuK, h_c), 0.001, {}},
                                          {0.089, period_thick(0.089, kMuK, h_c), 0.001, {}}};
  try {
    fit_through_rig(series, {.scene = scene, .gravity = 9.81});
    ADD_FAILURE() << "no error";
  } catch (const FitThroughRigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("row 1 (l = 30.0 mm): the scene simulated at mu_k = 0.29"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("the plate left the rollers"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace fl
