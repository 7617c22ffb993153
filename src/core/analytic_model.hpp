// The analytic friction (Timoshenko) oscillator: the paper's thin-plate formula and the
// thick-plate formula with the centre of mass a height h_c above the rollers' contact line.
//
//   thin:   T = pi sqrt(2 l / (mu_k g))                mu_k = 2 pi^2 l / (g T^2)
//   thick:  T = pi sqrt(2 (l - 2 mu_k h_c) / (mu_k g))  mu_k = 2 pi^2 l / (g T^2 + 4 pi^2 h_c)
//
// All quantities SI. Every function refuses inputs where it has no meaning with
// fl::DomainError (never a NaN).
#pragma once

#include <stdexcept>

namespace fl {

// An input outside the domain where a formula means anything (T <= 0, l <= 2 mu_k h_c, ...).
class DomainError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Local gravity used by the paper's rig unless a scene says otherwise [m/s^2].
inline constexpr double kDefaultGravity = 9.81;

// Period of the thin plate (h_c = 0), the paper's Eq. (period) [s].
double period_thin(double spacing, double mu_k, double gravity = kDefaultGravity);

// Period with the centre of mass h_c [m] above the contact line [s]. Requires l > 2 mu_k h_c.
double period_thick(double spacing, double mu_k, double h_c, double gravity = kDefaultGravity);

// mu_k from a measured period, thin-plate formula.
double mu_k_from_period_thin(double period, double spacing, double gravity = kDefaultGravity);

// mu_k from a measured period, thick-plate formula (closed form).
double mu_k_from_period_thick(double period, double spacing, double h_c,
                              double gravity = kDefaultGravity);

// mu_k and how errors in T and l carry into it.
struct MuKUncertainty {
  double mu_k = 0.0;
  double worst = 0.0;       // d mu = mu (dl/l kappa_l + dT/T kappa_T), the paper's form for h_c = 0
  double quadrature = 0.0;  // d mu = mu sqrt((kappa_l dl/l)^2 + (kappa_T dT/T)^2)
  double condition_period = 0.0;   // kappa_T = |d ln mu / d ln T| (2 for the thin plate)
  double condition_spacing = 0.0;  // kappa_l = |d ln mu / d ln l| (1)
  // kappa_h = |d ln mu / d ln h_c| = 4 pi^2 h_c / (g T^2 + 4 pi^2 h_c): near 1 (and kappa_T near
  // 0) the period no longer pins mu_k down: mu_k tends to l / (2 h_c), set by the plate's build.
  double condition_h_c = 0.0;
};

// mu_k +- d mu_k from T +- dT and l +- dl, through the thick formula (h_c = 0 gives the paper's
// d mu/mu = dl/l + 2 dT/T).
MuKUncertainty mu_k_with_uncertainty(double period, double period_err, double spacing,
                                     double spacing_err, double h_c = 0.0,
                                     double gravity = kDefaultGravity);

// Angular frequency of the oscillation, 2 pi / T_thick [rad/s].
double angular_frequency(double spacing, double mu_k, double h_c, double gravity = kDefaultGravity);

// The largest |x| of a harmonic oscillation at angular frequency omega [rad/s] that starts at x0
// [m] with speed v0 [m/s]: sqrt(x0^2 + (v0 / omega)^2).
double amplitude_from_start(double offset, double velocity, double omega);

// Roller angular speed [rad/s] at which the roller's surface just keeps up with the plate's
// largest speed A omega: below it the plate sticks to a roller for part of each cycle.
double roller_speed_for_full_slip(double amplitude, double roller_radius, double spacing,
                                  double mu_k, double h_c, double gravity = kDefaultGravity);

// Roller surface speed over the plate's largest speed; > 1 means both rollers slip throughout.
double slip_margin(double roller_speed, double roller_radius, double amplitude, double spacing,
                   double mu_k, double h_c, double gravity = kDefaultGravity);

// Offset of the centre of mass at which a normal force reaches zero while sliding:
// |x| = l/2 - mu_k h_c. Beyond it the plate tips (lifts off the far roller).
double tipping_amplitude(double spacing, double mu_k, double h_c);

// Whether a restoring force exists at all: l > 2 mu_k h_c (with rollers turning inward).
bool has_restoring_force(double spacing, double mu_k, double h_c);

}  // namespace fl
