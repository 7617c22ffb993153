#include "core/oscillation_tracker.hpp"

#include <cmath>

namespace fl {
namespace {

// Cubic Hermite on [0, 1] through (0, p0) and (1, p1) with slopes m0, m1 (already times h).
double hermite(double s, double p0, double p1, double m0, double m1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * m1;
}

double hermite_slope(double s, double p0, double p1, double m0, double m1) {
  const double s2 = s * s;
  return (6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * p1 +
         (3 * s2 - 2 * s) * m1;
}

// Root of f in [0, 1] given f(0) and f(1) of opposite signs: a few safeguarded Newton steps
// from the linear guess. A guess whose Newton correction is below 1e-15 is the root: tested before
// the bracket is, because a correction under an ulp leaves the next guess on the bracket's edge,
// where the bisection that guards the bracket would walk away from the root.
template <typename F, typename DF>
double root_in_unit(F f, DF df, double f0, double f1) {
  double lo = 0.0, hi = 1.0;
  double s = f0 / (f0 - f1);
  for (int i = 0; i < 20; ++i) {
    const double value = f(s);
    if (value == 0.0) return s;
    const double slope = df(s);
    if (slope != 0.0 && std::fabs(value / slope) < 1e-15) return s;
    if ((value < 0) == (f0 < 0))
      lo = s;
    else
      hi = s;
    double next = slope != 0.0 ? s - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - s) < 1e-15) return next;
    s = next;
  }
  return s;
}

}  // namespace

LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LinearFit fit;
  fit.n = x.size();
  if (fit.n < 2) return fit;
  const double n = static_cast<double>(fit.n);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < fit.n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < fit.n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  if (fit.n > 2) {
    double ss = 0;
    for (std::size_t i = 0; i < fit.n; ++i) {
      const double r = y[i] - (fit.intercept + fit.slope * x[i]);
      ss += r * r;
    }
    fit.residual_sd = std::sqrt(ss / (n - 2.0));
    fit.slope_std_error = std::sqrt(ss / (n - 2.0) / sxx);
  }
  return fit;
}

void OscillationTracker::add(double t, double x, double v) {
  const double y = x - centre_;
  if (have_previous_) {
    const double h = t - t0_;
    const double y0 = x0_ - centre_;
    const double m0 = v0_ * h, m1 = v * h;
    const auto f = [&](double s) { return hermite(s, y0, y, m0, m1); };
    const auto df = [&](double s) { return hermite_slope(s, y0, y, m0, m1); };
    // A crossing of the centre: the position changes sign (a sample exactly at the centre counts
    // once, with the sample after it).
    if ((y0 < 0.0 && y >= 0.0) || (y0 > 0.0 && y <= 0.0)) {
      const double s = y == 0.0 ? 1.0 : root_in_unit(f, df, y0, y);
      crossings_.push_back(t0_ + s * h);
    }
    // A turning point: the velocity changes sign.
    if ((v0_ > 0.0 && v <= 0.0) || (v0_ < 0.0 && v >= 0.0)) {
      const double s = v == 0.0 ? 1.0
                                : root_in_unit(
                                      df,
                                      [&](double u) {
                                        return (12 * u - 6) * y0 + (6 * u - 4) * m0 +
                                               (-12 * u + 6) * y + (6 * u - 2) * m1;
                                      },
                                      m0, m1);
      const double turn = f(s);
      amplitudes_.push_back(std::fabs(turn));
      turning_times_.push_back(t0_ + s * h);
      turning_positions_.push_back(turn + centre_);
    }
  }
  t0_ = t;
  x0_ = x;
  v0_ = v;
  have_previous_ = true;
}

std::optional<LinearFit> OscillationTracker::period(double since) const {
  std::vector<double> times;
  for (const double t : crossings_)
    if (t >= since) times.push_back(t);
  if (times.size() < 3) return std::nullopt;
  std::vector<double> index(times.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = 0.5 * static_cast<double>(i);
  return fit_line(index, times);
}

std::optional<double> OscillationTracker::centre(double since) const {
  double sum = 0.0;
  int pairs = 0;
  for (std::size_t k = 1; k < turning_positions_.size(); ++k) {
    if (turning_times_[k - 1] < since) continue;
    sum += 0.5 * (turning_positions_[k - 1] + turning_positions_[k]);
    ++pairs;
  }
  if (pairs == 0) return std::nullopt;
  return sum / pairs;
}

std::optional<double> OscillationTracker::amplitude_drift_per_period() const {
  const auto p = period();
  if (!p || amplitudes_.size() < 2) return std::nullopt;
  const LinearFit fit = fit_line(turning_times_, amplitudes_);
  return fit.slope * p->slope / amplitudes_.front();
}

}  // namespace fl
