#include "core/friction_oscillator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/domain_check.hpp"
#include "core/units.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

// Omega^2 = 2 g mu / (l - 2 mu h_c), or a refusal when there is no restoring force.
double omega_at(const PlateOnRollers& plate, double mu) {
  const double arm = plate.spacing - 2.0 * mu * plate.h_c;
  if (!(arm > 0.0))
    throw DomainError(describe("no restoring force: l = ", plate.spacing, " m <= 2 mu h_c = ",
                               2.0 * mu * plate.h_c, " m (mu = ", mu, ", h_c = ", plate.h_c,
                               " m); the plate drifts off instead of oscillating"));
  return std::sqrt(2.0 * plate.gravity * mu / arm);
}

// Whether the law is positive up to max_slip and leaves a restoring force at mu(v): the
// conditions full_slip_surface_speed needs at each roller speed it tries, without throwing.
bool usable_at(const FrictionLaw& law, const PlateOnRollers& plate, double v) {
  const double mu_v = law.kinetic(v);
  return law.kinetic(2.0 * v) > 0.0 && mu_v > 0.0 && plate.spacing > 2.0 * mu_v * plate.h_c;
}

}  // namespace

void check_friction_law(const FrictionLaw& law, double max_slip) {
  check_non_negative(max_slip, "the largest slip speed", "m/s");
  check_positive(law.mu_k, "mu_k", "");
  require_domain(std::isfinite(law.mu_s) && law.mu_s >= law.mu_k,
                 describe("the static limit mu_s must be finite and >= mu_k = ", law.mu_k, ", got ",
                          law.mu_s));
  if (law.kind == FrictionLawKind::kCoulomb) return;
  // Without a static excess the Stribeck term is zero and v_s is not used (a linear law).
  if (law.mu_s != law.mu_k) check_positive(law.v_s, "the Stribeck speed v_s", "m/s");
  require_domain(std::isfinite(law.beta),
                 describe("the linear slope beta must be finite, got ", law.beta, " s/m"));
  // With beta >= 0, mu(s) >= mu_k > 0. With beta < 0 both terms fall, so the least mu on
  // [0, max_slip] is at max_slip.
  if (law.beta < 0.0) {
    const double mu_end = law.kinetic(max_slip);
    require_domain(mu_end > 0.0,
                   describe("the friction law is not positive at slip speeds up to ", max_slip,
                            " m/s: mu = ", mu_end, " there (beta = ", law.beta, " s/m)"));
  }
}

void check_plate(const PlateOnRollers& plate) {
  check_positive(plate.spacing, "the roller spacing l", "m");
  check_non_negative(plate.h_c, "the centre-of-mass height h_c", "m");
  check_positive(plate.gravity, "gravity g", "m/s^2");
}

double effective_mu(const FrictionLaw& law, double surface_speed) {
  check_positive(surface_speed, "the rollers' surface speed v_r", "m/s");
  check_friction_law(law, 2.0 * surface_speed);
  return law.kinetic(surface_speed);
}

double sliding_angular_frequency(const FrictionLaw& law, const PlateOnRollers& plate,
                                 double surface_speed) {
  check_plate(plate);
  return omega_at(plate, effective_mu(law, surface_speed));
}

double stick_break_offset(const FrictionLaw& law, const PlateOnRollers& plate,
                          double surface_speed) {
  check_plate(plate);
  check_positive(surface_speed, "the rollers' surface speed v_r", "m/s");
  check_friction_law(law, 2.0 * surface_speed);
  const double mu_far = law.kinetic(2.0 * surface_speed);
  return 0.5 * plate.spacing * (law.mu_s - mu_far) / (law.mu_s + mu_far);
}

bool stick_holds(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                 int roller, double offset) {
  check_plate(plate);
  check_positive(surface_speed, "the rollers' surface speed v_r", "m/s");
  check_friction_law(law, 2.0 * surface_speed);
  require_domain(roller == 0 || roller == 1, describe("a roller is 0 or 1, got ", roller));
  const double half = 0.5 * plate.spacing;
  require_domain(std::isfinite(offset) && std::abs(offset) < half,
                 describe("the offset x must lie between the rollers, |x| < l/2 = ", half,
                          " m, got ", offset, " m"));
  const double mu_far = law.kinetic(2.0 * surface_speed);
  // Loads per unit weight with no net friction force: N_0 = 1/2 - x/l, N_1 = 1/2 + x/l.
  const double n_near = roller == 0 ? half - offset : half + offset;
  const double n_far = plate.spacing - n_near;
  return mu_far * n_far <= law.mu_s * n_near;
}

double full_slip_surface_speed(const FrictionLaw& law, const PlateOnRollers& plate,
                               double amplitude) {
  check_plate(plate);
  check_positive(amplitude, "the amplitude A", "m");
  check_friction_law(law, 0.0);
  // f(v) = v - A Omega(mu(v)) < 0 at v = 0. Walk up in steps finer than the law's features (a
  // quarter of v_s below 6 v_s, where the Stribeck term has fallen to 2e-16 of its height; 1 %
  // of v above) to the first sign change, then bisect.
  const auto f = [&](double v) { return v - amplitude * omega_at(plate, law.kinetic(v)); };
  const double scale = amplitude * omega_at(plate, law.kinetic(0.0));
  const bool stribeck = law.kind == FrictionLawKind::kStribeck;
  double lo = 0.0;
  double hi = 0.0;
  for (;;) {
    double step = 0.01 * std::max(lo, scale);
    if (stribeck && lo < 6.0 * law.v_s) step = std::min(step, 0.25 * law.v_s);
    hi = lo + step;
    if (!usable_at(law, plate, hi))
      throw DomainError(describe(
          "the plate keeps up with the rollers at every surface speed up to ", hi,
          " m/s, where the law (mu = ", law.kinetic(hi), " at v_r, ", law.kinetic(2.0 * hi),
          " at 2 v_r) stops giving a restoring force or a positive mu"));
    if (f(hi) >= 0.0) break;
    lo = hi;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) >= 0.0 ? hi : lo) = mid;
  }
  return hi;
}

double full_slip_roller_speed(const FrictionLaw& law, const PlateOnRollers& plate, double amplitude,
                              double roller_radius) {
  check_positive(roller_radius, "the roller radius a", "m");
  return full_slip_surface_speed(law, plate, amplitude) / roller_radius;
}

double full_slip_margin(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                        double amplitude) {
  check_positive(amplitude, "the amplitude A", "m");
  return surface_speed / (amplitude * sliding_angular_frequency(law, plate, surface_speed));
}

LinearisedMotion linearised_motion(const FrictionLaw& law, const PlateOnRollers& plate,
                                   double surface_speed) {
  LinearisedMotion out;
  out.omega = sliding_angular_frequency(law, plate, surface_speed);
  out.mu = law.kinetic(surface_speed);
  out.slope = law.slope(surface_speed);
  const double arm = plate.spacing - 2.0 * out.mu * plate.h_c;
  out.gamma = -plate.gravity * plate.spacing * out.slope / (2.0 * arm);
  require_domain(std::abs(out.gamma) < out.omega,
                 describe("no oscillation: the law's slope mu'(v_r) = ", out.slope,
                          " s/m gives |gamma| = ", std::abs(out.gamma),
                          " 1/s >= Omega = ", out.omega, " rad/s (the plate creeps instead)"));
  out.period_0 = 2.0 * kPi / out.omega;
  out.period = 2.0 * kPi / std::sqrt((out.omega - out.gamma) * (out.omega + out.gamma));
  return out;
}

}  // namespace fl
