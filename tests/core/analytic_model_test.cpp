// The analytic model against values computed by hand (python, 17 digits) from the formulas in
// the paper and docs/physics.md, and its refusal of inputs where it means nothing.
#include "core/analytic_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

namespace fl {
namespace {

constexpr double kG = 9.81;

TEST(AnalyticModel, ThinPeriodMatchesHandValue) {
  // pi sqrt(2 * 0.089 / (0.29 * 9.81))
  EXPECT_NEAR(period_thin(0.089, 0.29, kG), 0.7858259589972741, 1e-14);
}

TEST(AnalyticModel, ThickPeriodMatchesHandValue) {
  // pi sqrt(2 (0.089 - 2 * 0.3 * 0.008) / (0.3 * 9.81)): DESIGN's "about 3 %" shift.
  EXPECT_NEAR(period_thick(0.089, 0.3, 0.008, kG), 0.7514944632884485, 1e-14);
  EXPECT_NEAR(period_thin(0.089, 0.3, kG), 0.7726178593411187, 1e-14);
  const double shift = period_thick(0.089, 0.3, 0.008, kG) / period_thin(0.089, 0.3, kG) - 1.0;
  EXPECT_NEAR(shift, -0.0273, 0.0005);
}

TEST(AnalyticModel, MuFromPeriodReproducesThePapersLegoRow) {
  // LEGO at 300 K: T = 0.79 s at l = 89 mm gives 0.2869..., printed 0.29.
  EXPECT_NEAR(mu_k_from_period_thin(0.79, 0.089, kG), 0.28694360995330204, 1e-14);
  EXPECT_NEAR(mu_k_from_period_thick(0.79, 0.089, 0.008, kG), 0.27286763268378356, 1e-14);
}

TEST(AnalyticModel, PeriodAndMuAreInverses) {
  for (double mu : {0.01, 0.05, 0.29, 1.0, 1.7, 10.0}) {
    for (double h : {0.0, 0.001, 0.004}) {
      if (0.089 <= 2.0 * mu * h) continue;
      const double t = period_thick(0.089, mu, h, kG);
      EXPECT_NEAR(mu_k_from_period_thick(t, 0.089, h, kG), mu, 1e-12 * mu) << mu << " " << h;
    }
  }
}

TEST(AnalyticModel, ThePapersUncertaintyAndItsQuadratureForm) {
  const MuKUncertainty u = mu_k_with_uncertainty(0.79, 0.03, 0.089, 0.002, 0.0, kG);
  const double rel_l = 0.002 / 0.089;
  const double rel_t = 2.0 * 0.03 / 0.79;
  EXPECT_NEAR(u.worst, u.mu_k * (rel_l + rel_t), 1e-15);
  EXPECT_NEAR(u.quadrature, u.mu_k * std::sqrt(rel_l * rel_l + rel_t * rel_t), 1e-15);
  EXPECT_NEAR(u.worst, 0.028241356576260132, 1e-12);  // printed 0.03
  EXPECT_DOUBLE_EQ(u.condition_period, 2.0);
  EXPECT_DOUBLE_EQ(u.condition_spacing, 1.0);
}

TEST(AnalyticModel, ThickConditionNumberIsBelowTwo) {
  // kappa_T = 2 g T^2 / (g T^2 + 4 pi^2 h_c): a finite h_c makes mu less sensitive to T.
  const double t = 0.79;
  const double h = 0.008;
  const double expected =
      2.0 * kG * t * t / (kG * t * t + 4.0 * std::numbers::pi * std::numbers::pi * h);
  const MuKUncertainty u = mu_k_with_uncertainty(t, 0.0, 0.089, 0.0, h, kG);
  EXPECT_NEAR(u.condition_period, expected, 1e-15);
  EXPECT_LT(u.condition_period, 2.0);
  // kappa_T / 2 + kappa_h = 1: what the period does not decide, the build (h_c) does.
  EXPECT_NEAR(0.5 * u.condition_period + u.condition_h_c, 1.0, 1e-15);
  // A numerical derivative agrees with the closed form.
  const double eps = 1e-6;
  const double numeric = -(std::log(mu_k_from_period_thick(t * (1 + eps), 0.089, h, kG)) -
                           std::log(mu_k_from_period_thick(t * (1 - eps), 0.089, h, kG))) /
                         (std::log1p(eps) - std::log1p(-eps));
  EXPECT_NEAR(numeric, u.condition_period, 1e-8);
}

TEST(AnalyticModel, SlipMarginAt200RpmIsBelowOneAsDesignSays) {
  // docs/physics.md: at 200 rpm, a = 10 mm: 0.21 m/s, below 0.24 m/s for A = 30 mm at T = 0.79 s.
  const double mu = mu_k_from_period_thin(0.79, 0.089, kG);
  const double rpm = 2.0 * std::numbers::pi / 60.0;
  EXPECT_NEAR(slip_margin(200.0 * rpm, 0.010, 0.030, 0.089, mu, 0.0, kG), 0.877777777777778, 1e-12);
  EXPECT_GT(slip_margin(1600.0 * rpm, 0.010, 0.030, 0.089, mu, 0.0, kG), 1.0);
  EXPECT_NEAR(roller_speed_for_full_slip(0.030, 0.010, 0.089, mu, 0.0, kG),
              0.030 * 2.0 * std::numbers::pi / 0.79 / 0.010, 1e-12);
}

TEST(AnalyticModel, TippingAmplitudeAndRestoringForce) {
  EXPECT_NEAR(tipping_amplitude(0.089, 0.3, 0.008), 0.0445 - 0.0024, 1e-15);
  EXPECT_DOUBLE_EQ(tipping_amplitude(0.089, 0.3, 0.0), 0.0445);
  EXPECT_TRUE(has_restoring_force(0.089, 0.3, 0.008));
  // Flexible foam, mu_k = 10: any h_c above 4.45 mm leaves no restoring force.
  EXPECT_TRUE(has_restoring_force(0.089, 10.0, 0.0044));
  EXPECT_FALSE(has_restoring_force(0.089, 10.0, 0.00445));
  EXPECT_FALSE(has_restoring_force(0.089, 10.0, 0.005));
}

TEST(AnalyticModel, RefusesInputsWithoutMeaning) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(period_thin(0.0, 0.3), DomainError);
  EXPECT_THROW(period_thin(-0.089, 0.3), DomainError);
  EXPECT_THROW(period_thin(0.089, 0.0), DomainError);
  EXPECT_THROW(period_thin(0.089, -0.3), DomainError);
  EXPECT_THROW(period_thin(nan, 0.3), DomainError);
  EXPECT_THROW(period_thin(0.089, inf), DomainError);
  EXPECT_THROW(period_thin(0.089, 0.3, 0.0), DomainError);
  EXPECT_THROW(period_thick(0.089, 10.0, 0.005), DomainError);  // l <= 2 mu h_c
  EXPECT_THROW(period_thick(0.089, 0.3, -0.001), DomainError);
  EXPECT_THROW(mu_k_from_period_thin(0.0, 0.089), DomainError);
  EXPECT_THROW(mu_k_from_period_thin(-0.79, 0.089), DomainError);
  EXPECT_THROW(mu_k_from_period_thin(nan, 0.089), DomainError);
  EXPECT_THROW(mu_k_with_uncertainty(0.79, -0.01, 0.089, 0.002), DomainError);
  EXPECT_THROW(tipping_amplitude(0.089, 10.0, 0.005), DomainError);
  EXPECT_THROW(slip_margin(100.0, 0.0, 0.03, 0.089, 0.3, 0.0), DomainError);
  try {
    period_thick(0.089, 10.0, 0.005);
  } catch (const DomainError& e) {
    EXPECT_NE(std::string(e.what()).find("no restoring force"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl
