// mu_k and h_c from periods measured at several roller spacings. The thick-plate period squared,
//
//   T^2 = (2 pi^2 / (mu_k g)) l - 4 pi^2 h_c / g,
//
// is a straight line in l: a weighted least-squares line y = s l + c through y_i = T_i^2 gives
// mu_k = 2 pi^2 / (g s) and h_c = -c g / (4 pi^2), their standard errors and correlation from
// the line's 2x2 covariance. Errors: sigma_y = 2 T dT; with a spacing error, the effective
// variance sigma^2 = (2 T dT)^2 + (s dl)^2, iterated with s to convergence (docs/physics.md).
// Knows nothing of files or command lines; SI throughout.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/analytic_model.hpp"

namespace fl {

// One measurement of the series.
struct SpacingPeriod {
  double spacing = 0.0;               // l [m], > 0
  double period = 0.0;                // T [s], > 0
  double period_err = 0.0;            // dT [s], one standard deviation, > 0
  std::optional<double> spacing_err;  // dl [m], >= 0; absent: the spacing taken as exact
};

struct ThickPlateFitOptions {
  double gravity = kDefaultGravity;  // [m/s^2]
  // The effective variance's iteration stops when the slope changes by less than this, relative.
  double tolerance = 1e-12;
  int max_iterations = 100;
};

// What the fit says about one row.
struct FitRow {
  double period_squared_err = 0.0;  // sigma of T^2 used as its weight (effective variance) [s^2]
  double mu_k_thin = 0.0;           // the paper's thin formula on this row: 2 pi^2 l / (g T^2)
  // The fitted line's period at this row's spacing, sqrt(s l + c) [s]; absent where the line is
  // at or below zero there (l <= 2 mu_k h_c: no restoring force at this spacing).
  std::optional<double> period_fit;
  // (T^2 - (s l + c)) / sigma: the row's residual in units of its error.
  double residual_sigma = 0.0;
};

struct ThickPlateFit {
  // The straight line T^2 = s l + c.
  double slope = 0.0;                       // s [s^2/m]
  double intercept = 0.0;                   // c [s^2]
  double slope_err = 0.0;                   // standard error of s [s^2/m]
  double intercept_err = 0.0;               // standard error of c [s^2]
  double slope_intercept_covariance = 0.0;  // [s^4/m]
  // From the line; absent when s <= 0 (T^2 not growing with l: no friction oscillator's series).
  std::optional<double> mu_k;
  std::optional<double> mu_k_err;
  std::optional<double> h_c;          // [m]; may come out below 0 within its error for a thin plate
  std::optional<double> h_c_err;      // [m]
  std::optional<double> correlation;  // of mu_k and h_c (that of s and c)
  double chi2 = 0.0;
  int degrees_of_freedom = 0;          // rows - 2
  std::optional<double> chi2_per_dof;  // absent with 0 degrees of freedom
  int iterations = 1;                  // of the effective variance (1 without spacing errors)
  bool converged = true;
  // The paper's thin formula for contrast: the weighted line through the origin, T^2 = s0 l,
  // with the same errors, mu_k = 2 pi^2 / (g s0), and its chi^2 (rows - 1 degrees of freedom).
  double thin_slope = 0.0;  // [s^2/m]
  double thin_slope_err = 0.0;
  double mu_k_thin_line = 0.0;
  double mu_k_thin_line_err = 0.0;
  double thin_chi2 = 0.0;
  std::vector<FitRow> rows;  // in the series' order
};

// Refuses with fl::DomainError fewer than 2 rows, a non-finite or non-positive spacing, period or
// period error, a negative spacing error, or spacings that are all equal (no line through them).
ThickPlateFit fit_thick_plate(std::span<const SpacingPeriod> series,
                              const ThickPlateFitOptions& options = {});

// The largest spacing at which the fitted line leaves no restoring force, 2 mu_k h_c (where
// T^2 = s l + c reaches zero, -c / s) [m]; absent when s <= 0.
std::optional<double> spacing_without_restoring_force(const ThickPlateFit& fit);

}  // namespace fl
