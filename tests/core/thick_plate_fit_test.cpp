// The spacing series' fit against independent truth: exact periods from the thick-plate closed
// form give back their mu_k and h_c to rounding; a small series against numpy.polyfit's weighted
// line (w = 1/sigma, cov = "unscaled"); and noisy series drawn from the closed form recover mu_k
// and h_c within their reported standard errors as often as a correct fit does (coverage).
#include "core/thick_plate_fit.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"

namespace fl {
namespace {

constexpr double kG = 9.81;
constexpr double kMuK = 0.29;
constexpr double kHc = 0.0036;  // m, the paper's LEGO plate

std::vector<double> spacings_60_to_120_mm() {
  return {0.060, 0.070, 0.080, 0.090, 0.100, 0.110, 0.120};
}

std::vector<SpacingPeriod> exact_series(std::optional<double> spacing_err = std::nullopt) {
  std::vector<SpacingPeriod> series;
  for (const double l : spacings_60_to_120_mm())
    series.push_back({l, period_thick(l, kMuK, kHc, kG), 0.002, spacing_err});
  return series;
}

TEST(ThickPlateFit, ExactPeriodsGiveBackMuKAndHcToRounding) {
  for (const std::optional<double> dl : {std::optional<double>(), std::optional<double>(0.001)}) {
    const ThickPlateFit fit = fit_thick_plate(exact_series(dl), {.gravity = kG});
    ASSERT_TRUE(fit.mu_k && fit.h_c);
    // Rounding: T^2 ~ 0.6 s^2 carries ~1e-16 relative; c = -0.014 s^2 is a difference of such
    // numbers, so h_c keeps ~1e-14 relative, far inside these bounds.
    EXPECT_NEAR(*fit.mu_k, kMuK, 1e-12 * kMuK);
    EXPECT_NEAR(*fit.h_c, kHc, 1e-11 * kHc);
    EXPECT_LT(fit.chi2, 1e-20);
    EXPECT_EQ(fit.degrees_of_freedom, 5);
    EXPECT_TRUE(fit.converged);
    for (const FitRow& row : fit.rows) EXPECT_LT(std::fabs(row.residual_sigma), 1e-9);
    // The thin formula on each row reads mu_k high by 4 pi^2 h_c / (g T^2) (analytic_model.hpp).
    for (std::size_t i = 0; i < fit.rows.size(); ++i) {
      const double l = spacings_60_to_120_mm()[i];
      EXPECT_NEAR(fit.rows[i].mu_k_thin,
                  mu_k_from_period_thin(period_thick(l, kMuK, kHc, kG), l, kG), 1e-14);
      EXPECT_NEAR(*fit.rows[i].period_fit, period_thick(l, kMuK, kHc, kG), 1e-13);
    }
    EXPECT_GT(fit.mu_k_thin_line, kMuK);  // a line forced through the origin: biased high
  }
}

TEST(ThickPlateFit, TwoRowsFitExactlyWithNoDegreesOfFreedom) {
  const std::vector<SpacingPeriod> two{{0.070, period_thick(0.070, kMuK, kHc, kG), 0.002, {}},
                                       {0.110, period_thick(0.110, kMuK, kHc, kG), 0.003, {}}};
  const ThickPlateFit fit = fit_thick_plate(two, {.gravity = kG});
  EXPECT_EQ(fit.degrees_of_freedom, 0);
  EXPECT_FALSE(fit.chi2_per_dof.has_value());  // not measured: null, never 0
  EXPECT_NEAR(*fit.mu_k, kMuK, 1e-12);
  EXPECT_NEAR(*fit.h_c, kHc, 1e-12);
}

TEST(ThickPlateFit, AgreesWithNumpysWeightedLine) {
  // numpy.polyfit(l, T**2, 1, w=1/(2 T dT), cov="unscaled"), 17 digits.
  const std::vector<SpacingPeriod> series{{0.060, 0.6460, 0.004, {}},
                                          {0.075, 0.7260, 0.005, {}},
                                          {0.089, 0.7905, 0.003, {}},
                                          {0.105, 0.8560, 0.006, {}},
                                          {0.120, 0.9190, 0.005, {}}};
  const ThickPlateFit fit = fit_thick_plate(series, {.gravity = kG});
  const double tol = 1e-9;  // numpy solves by lstsq (SVD): agreement to ~1e-13, bound far above
  EXPECT_NEAR(fit.slope, 7.093956214622591, tol * 7.1);
  EXPECT_NEAR(fit.intercept, -0.0072677951095769106, tol * 7.1);
  EXPECT_NEAR(fit.slope_err * fit.slope_err, 0.023075181062360943, tol * 0.023);
  EXPECT_NEAR(fit.intercept_err * fit.intercept_err, 0.00016404138275691093, tol * 0.023);
  EXPECT_NEAR(fit.slope_intercept_covariance, -0.0018964253761670701, tol * 0.023);
  const double residuals[] = {-0.20386566713980944, 0.3164020678901603, 0.16781404346747616,
                              -0.4732873272775723, 0.06028828671012256};
  double chi2 = 0.0;
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(fit.rows[i].residual_sigma, residuals[i], 1e-7);
    chi2 += residuals[i] * residuals[i];
  }
  EXPECT_NEAR(fit.chi2, chi2, 1e-7);
  EXPECT_NEAR(*fit.chi2_per_dof, chi2 / 3.0, 1e-7);
  // mu_k, h_c and their errors from numpy's line by hand: 2 pi^2/(g s), -c g/(4 pi^2).
  EXPECT_NEAR(*fit.mu_k, 0.2836431044754858, 1e-9);
  EXPECT_NEAR(*fit.h_c, 0.001805975881289631, 1e-11);
  EXPECT_NEAR(*fit.mu_k_err, 0.00607374123336573, 1e-9);
  EXPECT_NEAR(*fit.h_c_err, 0.0031826287482472947, 1e-11);
  EXPECT_NEAR(*fit.correlation, -0.974734838208992, 1e-9);
  // The thin line through the origin: sum(w l T^2) / sum(w l^2).
  EXPECT_NEAR(fit.thin_slope, 7.009935762935658, 1e-9);
  EXPECT_NEAR(fit.mu_k_thin_line, 0.28704282489545346, 1e-9);
}

TEST(ThickPlateFit, TheEffectiveVarianceAgreesWithNumpyIteratedByHand) {
  // The same series with dl; numpy.polyfit refitted with w = 1/sqrt((2 T dT)^2 + (s dl)^2) until
  // the slope stopped changing (5 fits), 17 digits.
  const std::vector<SpacingPeriod> series{{0.060, 0.6460, 0.004, 0.001},
                                          {0.075, 0.7260, 0.005, 0.0005},
                                          {0.089, 0.7905, 0.003, 0.001},
                                          {0.105, 0.8560, 0.006, 0.002},
                                          {0.120, 0.9190, 0.005, 0.001}};
  const ThickPlateFit fit = fit_thick_plate(series, {.gravity = kG});
  EXPECT_TRUE(fit.converged);
  EXPECT_GT(fit.iterations, 2);
  EXPECT_LT(fit.iterations, 20);
  const double tol = 1e-9;
  EXPECT_NEAR(fit.slope, 7.088942390759926, tol * 7.1);
  EXPECT_NEAR(fit.intercept, -0.006458548011419359, tol * 7.1);
  EXPECT_NEAR(fit.slope_err * fit.slope_err, 0.049777217637233875, tol * 0.05);
  EXPECT_NEAR(fit.intercept_err * fit.intercept_err, 0.0003630492597667717, tol * 0.05);
  EXPECT_NEAR(fit.slope_intercept_covariance, -0.004138582522096717, tol * 0.05);
  EXPECT_NEAR(fit.chi2, 0.17473187116159627, 1e-7);
}

TEST(ThickPlateFit, AFallingLineHasNoMuK) {
  const std::vector<SpacingPeriod> falling{{0.070, 0.90, 0.002, {}}, {0.110, 0.80, 0.002, {}}};
  const ThickPlateFit fit = fit_thick_plate(falling, {.gravity = kG});
  EXPECT_LT(fit.slope, 0.0);
  EXPECT_FALSE(fit.mu_k.has_value());
  EXPECT_FALSE(fit.h_c.has_value());
  EXPECT_FALSE(spacing_without_restoring_force(fit).has_value());
}

TEST(ThickPlateFit, TheSpacingWithoutRestoringForceIsTwoMuKHc) {
  const ThickPlateFit fit = fit_thick_plate(exact_series(), {.gravity = kG});
  EXPECT_NEAR(*spacing_without_restoring_force(fit), 2.0 * kMuK * kHc, 1e-13);
}

TEST(ThickPlateFit, RefusesWhatNoLineFits) {
  const auto refuses = [](std::vector<SpacingPeriod> series, const char* what) {
    try {
      fit_thick_plate(series);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const DomainError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refuses({{0.089, 0.79, 0.01, {}}}, "at least 2 rows");
  refuses({{0.089, 0.79, 0.01, {}}, {0.089, 0.80, 0.01, {}}}, "two different spacings");
  refuses({{0.089, -0.79, 0.01, {}}, {0.1, 0.80, 0.01, {}}}, "the period T");
  refuses({{0.089, 0.79, 0.0, {}}, {0.1, 0.80, 0.01, {}}}, "the period's uncertainty");
  refuses({{0.089, 0.79, 0.01, {}}, {NAN, 0.80, 0.01, {}}}, "the roller spacing");
  refuses({{0.089, 0.79, 0.01, -0.001}, {0.1, 0.80, 0.01, {}}}, "the spacing's uncertainty");
}

// Coverage: for Gaussian errors a correct fit puts the truth within +-1 reported standard error
// 68.27 % of the time. Over N independent series the fraction is binomial with standard deviation
// sqrt(p (1 - p) / N); the test allows 4 of those (a correct fit fails it once in ~16 000 runs;
// errors 20 % too small or too large move the fraction by ~0.1, ten of them). chi^2/dof has
// variance 2/dof per series, so its mean over N series is 1 within 4 sqrt(2 / (dof N)).
struct Coverage {
  double mu_k = 0.0;
  double h_c = 0.0;
  double chi2_per_dof = 0.0;
  int skipped = 0;
};

Coverage coverage(int series_count, double period_err, std::optional<double> spacing_err) {
  Coverage c;
  int counted = 0;
  for (int seed = 1; seed <= series_count; ++seed) {
    // std::normal_distribution: a generator independent of the lab's own (core/normal_draws).
    std::mt19937_64 engine(static_cast<std::uint64_t>(seed));
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<SpacingPeriod> series;
    for (const double l_true : spacings_60_to_120_mm()) {
      const double t = period_thick(l_true, kMuK, kHc, kG) + period_err * normal(engine);
      const double l = spacing_err ? l_true + *spacing_err * normal(engine) : l_true;
      series.push_back({l, t, period_err, spacing_err});
    }
    const ThickPlateFit fit = fit_thick_plate(series, {.gravity = kG});
    if (!fit.mu_k) {
      ++c.skipped;
      continue;
    }
    ++counted;
    c.mu_k += std::fabs(*fit.mu_k - kMuK) < *fit.mu_k_err ? 1.0 : 0.0;
    c.h_c += std::fabs(*fit.h_c - kHc) < *fit.h_c_err ? 1.0 : 0.0;
    c.chi2_per_dof += *fit.chi2_per_dof;
  }
  c.mu_k /= counted;
  c.h_c /= counted;
  c.chi2_per_dof /= counted;
  return c;
}

constexpr int kSeries = 2000;
constexpr double kOneSigma = 0.682689492137086;  // erf(1 / sqrt(2))

double coverage_band() {
  return 4.0 * std::sqrt(kOneSigma * (1.0 - kOneSigma) / kSeries);
}
double chi2_band() {
  return 4.0 * std::sqrt(2.0 / (5.0 * kSeries));
}  // 7 rows: 5 dof

TEST(ThickPlateFitCoverage, PeriodErrorsOnly) {
  // dT = 5 ms on T = 0.64 to 0.91 s: mu_k to about 2 %, h_c to about 1 mm.
  const Coverage c = coverage(kSeries, 0.005, std::nullopt);
  EXPECT_EQ(c.skipped, 0);
  EXPECT_NEAR(c.mu_k, kOneSigma, coverage_band());
  EXPECT_NEAR(c.h_c, kOneSigma, coverage_band());
  EXPECT_NEAR(c.chi2_per_dof, 1.0, chi2_band());
  RecordProperty("coverage_mu_k", std::to_string(c.mu_k));
  RecordProperty("coverage_h_c", std::to_string(c.h_c));
  RecordProperty("mean_chi2_per_dof", std::to_string(c.chi2_per_dof));
  std::printf("period errors: coverage mu_k %.4f, h_c %.4f (band %.4f +- %.4f), chi2/dof %.4f\n",
              c.mu_k, c.h_c, kOneSigma, coverage_band(), c.chi2_per_dof);
}

TEST(ThickPlateFitCoverage, PeriodAndSpacingErrorsThroughTheEffectiveVariance) {
  // dl = 1 mm moves T^2 by s dl = 7e-3 s^2, as much as dT = 5 ms does (2 T dT = 8e-3 s^2): a
  // fit that ignored dl would claim errors ~25 % too small and cover ~0.55 (numpy: 0.545).
  const Coverage c = coverage(kSeries, 0.005, 0.001);
  EXPECT_EQ(c.skipped, 0);
  EXPECT_NEAR(c.mu_k, kOneSigma, coverage_band());
  EXPECT_NEAR(c.h_c, kOneSigma, coverage_band());
  EXPECT_NEAR(c.chi2_per_dof, 1.0, chi2_band());
  std::printf("with dl: coverage mu_k %.4f, h_c %.4f (band %.4f +- %.4f), chi2/dof %.4f\n", c.mu_k,
              c.h_c, kOneSigma, coverage_band(), c.chi2_per_dof);
}

}  // namespace
}  // namespace fl
