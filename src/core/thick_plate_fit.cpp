#include "core/thick_plate_fit.hpp"

#include <cmath>
#include <numbers>

#include "core/domain_check.hpp"
#include "core/units.hpp"

namespace fl {
namespace {

constexpr double kTwoPiSquared = 2.0 * kPi * kPi;

struct Line {
  double slope = 0.0;
  double intercept = 0.0;
  double var_slope = 0.0;
  double var_intercept = 0.0;
  double covariance = 0.0;
};

// The weighted least-squares line through (x_i, y_i) with errors sigma_i: the normal equations
// in closed form (centred on the weighted mean of x, so a series far from l = 0 loses no digits).
Line weighted_line(std::span<const double> x, std::span<const double> y,
                   std::span<const double> sigma) {
  double sw = 0.0;
  double swx = 0.0;
  double swy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = 1.0 / (sigma[i] * sigma[i]);
    sw += w;
    swx += w * x[i];
    swy += w * y[i];
  }
  const double x_mean = swx / sw;
  const double y_mean = swy / sw;
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = 1.0 / (sigma[i] * sigma[i]);
    sxx += w * (x[i] - x_mean) * (x[i] - x_mean);
    sxy += w * (x[i] - x_mean) * (y[i] - y_mean);
  }
  Line line;
  line.slope = sxy / sxx;
  line.intercept = y_mean - line.slope * x_mean;
  line.var_slope = 1.0 / sxx;
  line.var_intercept = 1.0 / sw + x_mean * x_mean / sxx;
  line.covariance = -x_mean / sxx;
  return line;
}

void check_series(std::span<const SpacingPeriod> series) {
  require_domain(series.size() >= 2,
                 describe("a straight line needs at least 2 rows, got ", series.size()));
  bool distinct = false;
  for (const SpacingPeriod& row : series) {
    check_positive(row.spacing, "the roller spacing l", "m");
    check_positive(row.period, "the period T", "s");
    check_positive(row.period_err, "the period's uncertainty dT", "s");
    if (row.spacing_err) check_non_negative(*row.spacing_err, "the spacing's uncertainty dl", "m");
    distinct = distinct || row.spacing != series.front().spacing;
  }
  require_domain(distinct, describe("every spacing is ", series.front().spacing,
                                    " m: T^2 against l needs at least two different spacings"));
}

}  // namespace

ThickPlateFit fit_thick_plate(std::span<const SpacingPeriod> series,
                              const ThickPlateFitOptions& options) {
  check_series(series);
  check_positive(options.gravity, "gravity g", "m/s^2");
  const std::size_t n = series.size();
  std::vector<double> x(n);
  std::vector<double> y(n);
  std::vector<double> sigma_period(n);  // 2 T dT: dT carried into T^2 to first order
  std::vector<double> sigma(n);
  bool any_spacing_err = false;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = series[i].spacing;
    y[i] = series[i].period * series[i].period;
    sigma_period[i] = 2.0 * series[i].period * series[i].period_err;
    sigma[i] = sigma_period[i];
    any_spacing_err = any_spacing_err || series[i].spacing_err.value_or(0.0) > 0.0;
  }

  ThickPlateFit fit;
  Line line = weighted_line(x, y, sigma);
  if (any_spacing_err) {
    // Effective variance: an error dl in x moves y by s dl; the weights depend on the slope they
    // determine, so refit until the slope stops changing.
    fit.converged = false;
    while (fit.iterations < options.max_iterations) {
      for (std::size_t i = 0; i < n; ++i)
        sigma[i] = std::hypot(sigma_period[i], line.slope * series[i].spacing_err.value_or(0.0));
      const Line next = weighted_line(x, y, sigma);
      ++fit.iterations;
      const bool settled =
          std::fabs(next.slope - line.slope) <= options.tolerance * std::fabs(next.slope);
      line = next;
      if (settled) {
        fit.converged = true;
        break;
      }
    }
  }
  fit.slope = line.slope;
  fit.intercept = line.intercept;
  fit.slope_err = std::sqrt(line.var_slope);
  fit.intercept_err = std::sqrt(line.var_intercept);
  fit.slope_intercept_covariance = line.covariance;
  fit.correlation = line.covariance / (fit.slope_err * fit.intercept_err);
  const double g = options.gravity;
  if (line.slope > 0.0) {
    // mu = 2 pi^2 / (g s): d mu / d s = -mu / s. h = -c g / (4 pi^2): dh / dc = -g / (4 pi^2).
    // The two derivatives have the same sign, so corr(mu, h) = corr(s, c).
    fit.mu_k = kTwoPiSquared / (g * line.slope);
    fit.mu_k_err = *fit.mu_k / line.slope * fit.slope_err;
    fit.h_c = -line.intercept * g / (2.0 * kTwoPiSquared);
    fit.h_c_err = g / (2.0 * kTwoPiSquared) * fit.intercept_err;
  } else {
    fit.correlation.reset();
  }

  // The thin formula's line through the origin, with the same errors: s0 = sum(w x y)/sum(w x^2).
  double swxx = 0.0;
  double swxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 1.0 / (sigma[i] * sigma[i]);
    swxx += w * x[i] * x[i];
    swxy += w * x[i] * y[i];
  }
  fit.thin_slope = swxy / swxx;
  fit.thin_slope_err = 1.0 / std::sqrt(swxx);
  fit.mu_k_thin_line = kTwoPiSquared / (g * fit.thin_slope);
  fit.mu_k_thin_line_err = fit.mu_k_thin_line / fit.thin_slope * fit.thin_slope_err;

  fit.rows.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    FitRow& row = fit.rows[i];
    row.period_squared_err = sigma[i];
    row.mu_k_thin = kTwoPiSquared * x[i] / (g * y[i]);
    const double y_fit = line.slope * x[i] + line.intercept;
    if (y_fit > 0.0) row.period_fit = std::sqrt(y_fit);
    row.residual_sigma = (y[i] - y_fit) / sigma[i];
    fit.chi2 += row.residual_sigma * row.residual_sigma;
    const double thin_residual = (y[i] - fit.thin_slope * x[i]) / sigma[i];
    fit.thin_chi2 += thin_residual * thin_residual;
  }
  fit.degrees_of_freedom = static_cast<int>(n) - 2;
  if (fit.degrees_of_freedom > 0) fit.chi2_per_dof = fit.chi2 / fit.degrees_of_freedom;
  return fit;
}

std::optional<double> spacing_without_restoring_force(const ThickPlateFit& fit) {
  if (!(fit.slope > 0.0)) return std::nullopt;
  return -fit.intercept / fit.slope;
}

}  // namespace fl
