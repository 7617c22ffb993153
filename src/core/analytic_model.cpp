#include "core/analytic_model.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/domain_check.hpp"
#include "core/units.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

void check_oscillator(double spacing, double mu_k, double h_c, double gravity) {
  check_positive(spacing, "the roller spacing l", "m");
  check_positive(mu_k, "mu_k", "");
  check_non_negative(h_c, "the centre-of-mass height h_c", "m");
  check_positive(gravity, "gravity g", "m/s^2");
  require_domain(spacing > 2.0 * mu_k * h_c,
                 describe("no restoring force: l = ", spacing,
                          " m <= 2 mu_k h_c = ", 2.0 * mu_k * h_c, " m (mu_k = ", mu_k,
                          ", h_c = ", h_c, " m); the plate drifts off instead of oscillating"));
}

}  // namespace

double period_thin(double spacing, double mu_k, double gravity) {
  return period_thick(spacing, mu_k, 0.0, gravity);
}

double period_thick(double spacing, double mu_k, double h_c, double gravity) {
  check_oscillator(spacing, mu_k, h_c, gravity);
  return kPi * std::sqrt(2.0 * (spacing - 2.0 * mu_k * h_c) / (mu_k * gravity));
}

double mu_k_from_period_thin(double period, double spacing, double gravity) {
  return mu_k_from_period_thick(period, spacing, 0.0, gravity);
}

double mu_k_from_period_thick(double period, double spacing, double h_c, double gravity) {
  check_positive(period, "the period T", "s");
  check_positive(spacing, "the roller spacing l", "m");
  check_non_negative(h_c, "the centre-of-mass height h_c", "m");
  check_positive(gravity, "gravity g", "m/s^2");
  // mu g T^2 = 2 pi^2 (l - 2 mu h)  =>  mu = 2 pi^2 l / (g T^2 + 4 pi^2 h); always l > 2 mu h.
  return 2.0 * kPi * kPi * spacing / (gravity * period * period + 4.0 * kPi * kPi * h_c);
}

MuKUncertainty mu_k_with_uncertainty(double period, double period_err, double spacing,
                                     double spacing_err, double h_c, double gravity) {
  check_non_negative(period_err, "the period's uncertainty dT", "s");
  check_non_negative(spacing_err, "the spacing's uncertainty dl", "m");
  MuKUncertainty out;
  out.mu_k = mu_k_from_period_thick(period, spacing, h_c, gravity);
  const double denominator = gravity * period * period + 4.0 * kPi * kPi * h_c;
  out.condition_spacing = 1.0;
  out.condition_period = 2.0 * gravity * period * period / denominator;
  out.condition_h_c = 4.0 * kPi * kPi * h_c / denominator;
  const double rel_l = out.condition_spacing * spacing_err / spacing;
  const double rel_t = out.condition_period * period_err / period;
  out.worst = out.mu_k * (rel_l + rel_t);
  out.quadrature = out.mu_k * std::hypot(rel_l, rel_t);
  return out;
}

double angular_frequency(double spacing, double mu_k, double h_c, double gravity) {
  return 2.0 * kPi / period_thick(spacing, mu_k, h_c, gravity);
}

double amplitude_from_start(double offset, double velocity, double omega) {
  check_positive(omega, "the angular frequency omega", "rad/s");
  return std::hypot(offset, velocity / omega);
}

double roller_speed_for_full_slip(double amplitude, double roller_radius, double spacing,
                                  double mu_k, double h_c, double gravity) {
  check_non_negative(amplitude, "the amplitude A", "m");
  check_positive(roller_radius, "the roller radius a", "m");
  return amplitude * angular_frequency(spacing, mu_k, h_c, gravity) / roller_radius;
}

double slip_margin(double roller_speed, double roller_radius, double amplitude, double spacing,
                   double mu_k, double h_c, double gravity) {
  check_non_negative(roller_speed, "the roller speed", "rad/s");
  check_positive(amplitude, "the amplitude A", "m");
  return roller_speed /
         roller_speed_for_full_slip(amplitude, roller_radius, spacing, mu_k, h_c, gravity);
}

double tipping_amplitude(double spacing, double mu_k, double h_c) {
  check_oscillator(spacing, mu_k, h_c, kDefaultGravity);
  return 0.5 * spacing - mu_k * h_c;
}

bool has_restoring_force(double spacing, double mu_k, double h_c) {
  check_positive(spacing, "the roller spacing l", "m");
  check_positive(mu_k, "mu_k", "");
  check_non_negative(h_c, "the centre-of-mass height h_c", "m");
  return spacing > 2.0 * mu_k * h_c;
}

}  // namespace fl
