// mu_k by Monte Carlo against the linear propagation it must reduce to for small errors (the
// paper's quadrature rule, and its thick-plate form with h_c), the same bits from the same seed,
// and the refusals.
#include "core/mu_k_monte_carlo.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "core/normal_draws.hpp"

namespace fl {
namespace {

constexpr double kG = 9.81;
constexpr int kDraws = 200000;

// The sample standard deviation of N Gaussian draws has a relative standard error of
// 1 / sqrt(2 (N - 1)); 4 of those bound the MC sd against the exact one (0.63 % at 200 000).
// Linearisation leaves out terms of order (dT/T)^2 ~ 1e-6 relative at 0.1 % errors: far below.
double sd_tolerance(int draws) {
  return 4.0 / std::sqrt(2.0 * (draws - 1));
}

TEST(MuKMonteCarlo, SmallErrorsGiveTheQuadratureRule) {
  const MuKMeasurement m{.period = 0.79,
                         .period_err = 0.79e-3,
                         .spacing = 0.089,
                         .spacing_err = 0.089e-3,
                         .h_c = 0.0,
                         .h_c_err = 0.0,
                         .gravity = kG};
  const MuKMonteCarlo mc = mu_k_monte_carlo(m, {.draws = kDraws, .seed = 7});
  const MuKUncertainty rules = mu_k_with_uncertainty(0.79, 0.79e-3, 0.089, 0.089e-3, 0.0, kG);
  ASSERT_TRUE(mc.mu_k && mc.mu_k->sd);
  EXPECT_EQ(mc.accepted, kDraws);
  EXPECT_EQ(mc.skipped, 0);
  EXPECT_NEAR(*mc.mu_k->sd / rules.quadrature, 1.0, sd_tolerance(kDraws));
  // The mean: the standard error of a mean is sd / sqrt(N); 4 of those.
  EXPECT_NEAR(mc.mu_k->mean, rules.mu_k, 4.0 * rules.quadrature / std::sqrt(kDraws));
  // A Gaussian's 95 % interval is mean +- 1.95996 sd; the quantiles of N draws scatter by about
  // 2.7 sd / sqrt(N) (sqrt(p (1 - p)) / pdf at the quantile, 0.156 / 0.0584); 4 of those.
  const double q_tol = 4.0 * 2.7 * rules.quadrature / std::sqrt(kDraws);
  EXPECT_NEAR(mc.mu_k->quantile_025, rules.mu_k - 1.959964 * rules.quadrature, q_tol);
  EXPECT_NEAR(mc.mu_k->quantile_975, rules.mu_k + 1.959964 * rules.quadrature, q_tol);
  EXPECT_EQ(mc.samples.size(), static_cast<std::size_t>(kDraws));
  std::printf("MC sd / quadrature = %.5f (tolerance %.5f)\n", *mc.mu_k->sd / rules.quadrature,
              sd_tolerance(kDraws));
}

TEST(MuKMonteCarlo, ThickPlateWithAnUncertainHcGivesTheLinearPropagation) {
  // d mu = mu sqrt((kappa_l dl/l)^2 + (kappa_T dT/T)^2 + (kappa_h dh/h)^2), the kappas from
  // mu_k_with_uncertainty; kappa_h = 4 pi^2 h_c / (g T^2 + 4 pi^2 h_c).
  const MuKMeasurement m{.period = 0.79,
                         .period_err = 0.79e-3,
                         .spacing = 0.089,
                         .spacing_err = 0.089e-3,
                         .h_c = 0.0036,
                         .h_c_err = 0.0036e-3,
                         .gravity = kG};
  const MuKMonteCarlo mc = mu_k_monte_carlo(m, {.draws = kDraws, .seed = 11});
  const MuKUncertainty u = mu_k_with_uncertainty(0.79, 0.79e-3, 0.089, 0.089e-3, 0.0036, kG);
  const double linear = u.mu_k * std::sqrt(std::pow(u.condition_spacing * 1e-3, 2) +
                                           std::pow(u.condition_period * 1e-3, 2) +
                                           std::pow(u.condition_h_c * 1e-3, 2));
  EXPECT_NEAR(*mc.mu_k->sd / linear, 1.0, sd_tolerance(kDraws));
  // Without dh_c the MC is the quadrature rule of the thick formula.
  MuKMeasurement fixed_h = m;
  fixed_h.h_c_err = 0.0;
  const MuKMonteCarlo no_h = mu_k_monte_carlo(fixed_h, {.draws = kDraws, .seed = 11});
  EXPECT_NEAR(*no_h.mu_k->sd / u.quadrature, 1.0, sd_tolerance(kDraws));
}

TEST(MuKMonteCarlo, TheSameSeedGivesTheSameBitsAndAnotherSeedOthers) {
  const MuKMeasurement m{
      .period = 0.79, .period_err = 0.03, .spacing = 0.089, .spacing_err = 0.002};
  const MuKMonteCarlo a = mu_k_monte_carlo(m, {.draws = 1000, .seed = 3});
  const MuKMonteCarlo b = mu_k_monte_carlo(m, {.draws = 1000, .seed = 3});
  const MuKMonteCarlo c = mu_k_monte_carlo(m, {.draws = 1000, .seed = 4});
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) EXPECT_EQ(a.samples[i], b.samples[i]) << i;
  EXPECT_EQ(a.mu_k->mean, b.mu_k->mean);
  EXPECT_EQ(*a.mu_k->sd, *b.mu_k->sd);
  EXPECT_NE(a.samples, c.samples);
  EXPECT_NE(a.mu_k->mean, c.mu_k->mean);
}

TEST(MuKMonteCarlo, DrawsOutsideTheFormulasDomainAreSkippedAndCounted) {
  // dT = T: about 16 % of the periods are drawn <= 0; h_c = 0 +- 1 mm: half the heights < 0.
  const MuKMeasurement m{.period = 0.79,
                         .period_err = 0.79,
                         .spacing = 0.089,
                         .spacing_err = 0.0,
                         .h_c = 0.0,
                         .h_c_err = 0.001};
  const MuKMonteCarlo mc = mu_k_monte_carlo(m, {.draws = 20000, .seed = 5});
  EXPECT_EQ(mc.accepted + mc.skipped, 20000);
  // P(accepted) = P(T > 0) P(h >= 0) = 0.8413 x 0.5; binomial, 4 sigma.
  const double p = 0.841344746 * 0.5;
  EXPECT_NEAR(mc.accepted / 20000.0, p, 4.0 * std::sqrt(p * (1 - p) / 20000.0));
  EXPECT_EQ(mc.samples.size(), static_cast<std::size_t>(mc.accepted));
  for (const double mu : mc.samples) EXPECT_GT(mu, 0.0);
}

TEST(MuKMonteCarlo, RefusesNoDrawsAndMeasurementsOutsideTheDomain) {
  const MuKMeasurement m{.period = 0.79, .period_err = 0.01, .spacing = 0.089};
  EXPECT_THROW(mu_k_monte_carlo(m, {.draws = 0}), DomainError);
  EXPECT_THROW(mu_k_monte_carlo(m, {.draws = -5}), DomainError);
  MuKMeasurement bad = m;
  bad.period = -0.79;
  EXPECT_THROW(mu_k_monte_carlo(bad, {.draws = 10}), DomainError);
  bad = m;
  bad.h_c_err = -1e-3;
  EXPECT_THROW(mu_k_monte_carlo(bad, {.draws = 10}), DomainError);
}

TEST(NormalDraws, StandardNormalMomentsAndOneSigmaFraction) {
  NormalDraws normal(42);
  constexpr int kN = 400000;
  double sum = 0.0;
  double squares = 0.0;
  int within = 0;
  for (int i = 0; i < kN; ++i) {
    const double z = normal.standard();
    sum += z;
    squares += z * z;
    within += std::fabs(z) < 1.0 ? 1 : 0;
  }
  // Mean 0 +- 4/sqrt(N); variance 1 +- 4 sqrt(2/N); fraction 0.6827 binomial +- 4 sigma.
  EXPECT_NEAR(sum / kN, 0.0, 4.0 / std::sqrt(kN));
  EXPECT_NEAR(squares / kN, 1.0, 4.0 * std::sqrt(2.0 / kN));
  const double p = 0.682689492137086;
  EXPECT_NEAR(static_cast<double>(within) / kN, p, 4.0 * std::sqrt(p * (1 - p) / kN));
}

TEST(NormalDraws, AZeroSpreadGivesTheMeanExactly) {
  NormalDraws normal(1);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(normal.next(0.089, 0.0), 0.089);
}

}  // namespace
}  // namespace fl
