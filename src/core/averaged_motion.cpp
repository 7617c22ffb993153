#include "core/averaged_motion.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/analytic_model.hpp"
#include "core/units.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

struct SlipTerms {
  double omega2 = 0.0;  // Omega^2(v) [1/s^2]
  double force = 0.0;   // F(v) [m/s^2]
};

// The slipping plate's stiffness and slip-dependent force at speed v, |v| <= v_r.
SlipTerms slip_terms(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                     double v) {
  const double mu_0 = law.kinetic(surface_speed - v);
  const double mu_1 = law.kinetic(surface_speed + v);
  const double sigma = 0.5 * (mu_0 + mu_1);
  const double delta = 0.5 * (mu_0 - mu_1);
  const double arm = plate.spacing - 2.0 * plate.h_c * sigma;
  if (!(arm > 0.0))
    throw DomainError(describe("no restoring force at plate speed ", v, " m/s: l = ", plate.spacing,
                               " m <= 2 h_c sigma = ", 2.0 * plate.h_c * sigma, " m"));
  return {2.0 * plate.gravity * sigma / arm, plate.gravity * plate.spacing * delta / arm};
}

// (1 / 2 pi) Int_0^2pi f(t) dt by the trapezoidal rule, doubling the points until two estimates
// agree to `tolerance` (absolute) or 2^20 points.
template <typename Integrand>
double periodic_mean(const Integrand& f, double tolerance) {
  int n = 64;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += f(2.0 * kPi * i / n);
  double mean = sum / n;
  while (n < (1 << 20)) {
    double odd = 0.0;
    for (int i = 0; i < n; ++i) odd += f(2.0 * kPi * (i + 0.5) / n);
    sum += odd;
    n *= 2;
    const double next = sum / n;
    const bool settled = std::abs(next - mean) <= tolerance;
    mean = next;
    if (settled) break;
  }
  return mean;
}

// Int_a^b f(t) dt by Simpson's rule, doubling the panels until two estimates agree to
// `tolerance` (absolute) or 2^20 panels.
template <typename Integrand>
double interval_integral(const Integrand& f, double a, double b, double tolerance) {
  int n = 64;
  const double ends = f(a) + f(b);
  double even = 0.0;  // interior points shared with the coarser grid
  for (int i = 1; i < n; ++i) even += f(a + (b - a) * i / n);
  double odd = 0.0;
  for (int i = 0; i < n; ++i) odd += f(a + (b - a) * (i + 0.5) / n);
  double estimate = (b - a) / (6.0 * n) * (ends + 2.0 * even + 4.0 * odd);
  while (n < (1 << 20)) {
    even += odd;
    n *= 2;
    odd = 0.0;
    for (int i = 0; i < n; ++i) odd += f(a + (b - a) * (i + 0.5) / n);
    const double next = (b - a) / (6.0 * n) * (ends + 2.0 * even + 4.0 * odd);
    const bool settled = std::abs(next - estimate) <= tolerance;
    estimate = next;
    if (settled) break;
  }
  return estimate;
}

struct Cycle {
  double omega_0 = 0.0;
  double speed = 0.0;  // V = A Omega_0, at most v_r
};

Cycle check_cycle(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                  double amplitude) {
  Cycle c;
  c.omega_0 = sliding_angular_frequency(law, plate, surface_speed);
  const double reach = surface_speed / c.omega_0;
  if (!(std::isfinite(amplitude) && amplitude > 0.0 && amplitude <= reach * (1.0 + 1e-12)))
    throw DomainError(describe("the averaged motion needs 0 < A <= v_r / Omega = ", reach,
                               " m (a larger cycle reaches a roller's speed), got ", amplitude,
                               " m"));
  c.speed = std::min(amplitude * c.omega_0, surface_speed);
  return c;
}

}  // namespace

double averaged_growth_rate(const FrictionLaw& law, const PlateOnRollers& plate,
                            double surface_speed, double amplitude) {
  const Cycle c = check_cycle(law, plate, surface_speed, amplitude);
  const double tolerance = 1e-13 * plate.gravity;
  const double mean = periodic_mean(
      [&](double t) {
        const double s = std::sin(t);
        return slip_terms(law, plate, surface_speed, c.speed * s).force * s;
      },
      tolerance);
  return mean / c.speed;
}

double averaged_period(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                       double amplitude) {
  const Cycle c = check_cycle(law, plate, surface_speed, amplitude);
  const double omega2_0 = c.omega_0 * c.omega_0;
  const double mean = periodic_mean(
      [&](double t) {
        const double co = std::cos(t);
        return (slip_terms(law, plate, surface_speed, c.speed * std::sin(t)).omega2 - omega2_0) *
               co * co;
      },
      1e-13 * omega2_0);
  const double omega = c.omega_0 + mean / c.omega_0;
  const double gamma = averaged_growth_rate(law, plate, surface_speed, amplitude);
  if (!(std::abs(gamma) < omega))
    throw DomainError(describe("no oscillation at amplitude ", amplitude, " m: |gamma| = ",
                               std::abs(gamma), " 1/s >= omega = ", omega, " rad/s"));
  return 2.0 * kPi / std::sqrt((omega - gamma) * (omega + gamma));
}

double slip_arc_energy_gain(const FrictionLaw& law, const PlateOnRollers& plate,
                            double surface_speed) {
  const double omega_0 = sliding_angular_frequency(law, plate, surface_speed);
  const double x_b = stick_break_offset(law, plate, surface_speed);
  if (!(x_b > 0.0))
    throw DomainError(describe("the slip arc between sticks needs a break offset x_b > 0, got ",
                               x_b, " m (mu(2 v_r) >= mu_s)"));
  const double arc = std::hypot(x_b, surface_speed / omega_0);
  const double t1 = std::atan2(surface_speed, omega_0 * x_b);
  const double speed = arc * omega_0;  // speed * sin(t1) = v_r
  // The integrand is even in t: twice the integral over [0, t1].
  const double integral = interval_integral(
      [&](double t) {
        const double s = std::sin(t);
        return slip_terms(law, plate, surface_speed, speed * s).force * s;
      },
      0.0, t1, 1e-13 * plate.gravity);
  return 2.0 * arc * integral;
}

}  // namespace fl
