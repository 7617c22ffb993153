// The fit's Monte Carlo against the fit's own linear propagation, which it must reproduce when
// the errors are small; the same bits from the same seed; the refusals.
#include "core/thick_plate_fit_monte_carlo.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"

namespace fl {
namespace {

constexpr double kG = 9.81;

std::vector<SpacingPeriod> series(double period_err, std::optional<double> spacing_err) {
  std::vector<SpacingPeriod> out;
  for (const double l : {0.060, 0.070, 0.080, 0.090, 0.100, 0.110, 0.120})
    out.push_back({l, period_thick(l, 0.29, 0.0036, kG), period_err, spacing_err});
  return out;
}

constexpr int kDraws = 20000;
// A sample sd of N draws: relative standard error 1 / sqrt(2 (N - 1)), 4 of those (2.8 %).
// mu_k = 2 pi^2 / (g s) with s known to 0.3 % here: its non-linearity changes the sd by ~1e-5.
const double kSdTolerance = 4.0 / std::sqrt(2.0 * (kDraws - 1));

TEST(ThickPlateFitMonteCarlo, SmallErrorsGiveTheFitsStandardErrors) {
  for (const std::optional<double> dl : {std::optional<double>(), std::optional<double>(2e-4)}) {
    const std::vector<SpacingPeriod> s = series(0.5e-3, dl);
    const ThickPlateFit fit = fit_thick_plate(s, {.gravity = kG});
    const ThickPlateFitMonteCarlo mc =
        thick_plate_fit_monte_carlo(s, {.gravity = kG}, {.draws = kDraws, .seed = 9});
    EXPECT_EQ(mc.accepted, kDraws);
    EXPECT_EQ(mc.skipped, 0);
    EXPECT_NEAR(*mc.mu_k->sd / *fit.mu_k_err, 1.0, kSdTolerance);
    EXPECT_NEAR(*mc.h_c->sd / *fit.h_c_err, 1.0, kSdTolerance);
    // Sample correlation: standard error (1 - rho^2) / sqrt(N); 4 of those.
    const double rho = *fit.correlation;
    EXPECT_NEAR(*mc.correlation, rho, 4.0 * (1.0 - rho * rho) / std::sqrt(kDraws));
    // Means: within 4 standard errors of the fitted values.
    EXPECT_NEAR(mc.mu_k->mean, *fit.mu_k, 4.0 * *fit.mu_k_err / std::sqrt(kDraws));
    EXPECT_NEAR(mc.h_c->mean, *fit.h_c, 4.0 * *fit.h_c_err / std::sqrt(kDraws));
    std::printf("dl %s: MC sd / fit's error: mu_k %.4f, h_c %.4f; correlation %.4f vs %.4f\n",
                dl ? "0.2 mm" : "none", *mc.mu_k->sd / *fit.mu_k_err, *mc.h_c->sd / *fit.h_c_err,
                *mc.correlation, rho);
  }
}

TEST(ThickPlateFitMonteCarlo, TheSameSeedGivesTheSameBits) {
  const std::vector<SpacingPeriod> s = series(5e-3, 1e-3);
  const auto a = thick_plate_fit_monte_carlo(s, {.gravity = kG}, {.draws = 500, .seed = 2});
  const auto b = thick_plate_fit_monte_carlo(s, {.gravity = kG}, {.draws = 500, .seed = 2});
  const auto c = thick_plate_fit_monte_carlo(s, {.gravity = kG}, {.draws = 500, .seed = 3});
  EXPECT_EQ(a.mu_k_samples, b.mu_k_samples);
  EXPECT_EQ(a.h_c_samples, b.h_c_samples);
  EXPECT_NE(a.mu_k_samples, c.mu_k_samples);
}

TEST(ThickPlateFitMonteCarlo, RefusesNoDrawsAndASeriesTheFitRefuses) {
  const std::vector<SpacingPeriod> s = series(5e-3, std::nullopt);
  EXPECT_THROW(thick_plate_fit_monte_carlo(s, {}, {.draws = 0}), DomainError);
  EXPECT_THROW(thick_plate_fit_monte_carlo(std::vector<SpacingPeriod>(s.begin(), s.begin() + 1), {},
                                           {.draws = 10}),
               DomainError);
}

}  // namespace
}  // namespace fl
