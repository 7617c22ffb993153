#include "core/friction_regime.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/analytic_model.hpp"
#include "core/averaged_motion.hpp"
#include "core/domain_check.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// What the slip-dependent cases need, computed once.
struct SlipDependentCase {
  const FrictionLaw& law;
  const PlateOnRollers& plate;
  double surface_speed = 0.0;
  double omega = 0.0;
  double reach = 0.0;  // v_r / Omega [m]
  double tipping = 0.0;
  double x_b = 0.0;

  double rate(double amplitude) const {
    return averaged_growth_rate(law, plate, surface_speed, std::min(amplitude, reach));
  }

  // The first amplitude between `from` and `to` (either order) where gamma(A) changes sign: a
  // scan of 64 steps (geometric) refined by bisection. None if gamma keeps its sign.
  std::optional<double> first_root(double from, double to) const {
    constexpr int kSteps = 64;
    const double ratio = std::pow(to / from, 1.0 / kSteps);
    double a = from;
    double ga = rate(a);
    for (int i = 1; i <= kSteps; ++i) {
      const double b = i == kSteps ? to : from * std::pow(ratio, i);
      const double gb = rate(b);
      if ((ga > 0.0) != (gb > 0.0)) {
        double lo = a;
        double hi = b;
        for (int k = 0; k < 100 && std::abs(hi - lo) > 1e-14 * std::abs(hi); ++k) {
          const double mid = 0.5 * (lo + hi);
          ((rate(mid) > 0.0) == (ga > 0.0) ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
      }
      a = b;
      ga = gb;
    }
    return std::nullopt;
  }

  // The averaged time for the amplitude to go from `from` to `to`, Int dA / (A gamma(A)) by
  // Simpson's rule in ln A (64 panels); +infinity if gamma has the wrong sign on the way.
  double travel_time(double from, double to) const {
    constexpr int kPanels = 64;
    const double span = std::log(to / from);
    double sum = 0.0;
    for (int i = 0; i <= kPanels; ++i) {
      const double g = rate(from * std::exp(span * i / kPanels));
      if (!(g * span > 0.0)) return kInfinity;
      const double weight = (i == 0 || i == kPanels) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += weight / g;
    }
    return span / (3.0 * kPanels) * sum;
  }
};

// After a stick, a slip-dependent law. The stick ends at +-x_b with the plate at the roller's
// speed; the slip arc that follows (harmonic at first order, its energy changed by dE) reaches the
// other roller's speed if Omega^2 x_b^2 + 2 dE >= 0 (x_b > 0): then the stick-slip cycle
// persists. Otherwise the plate goes on slipping at the amplitude the arc left it,
// A = sqrt((v_r / Omega)^2 + (Omega^2 x_b^2 + 2 dE) / Omega^2) (v_r / Omega when x_b <= 0, where
// the stick ends at a speed maximum): if gamma(A) >= 0 it grows back to a roller's speed (the
// stick-slip persists), else it shrinks to the largest slip cycle below A, or to rest.
void after_stick(const SlipDependentCase& slip, FrictionRegimePrediction& out) {
  const double omega2 = slip.omega * slip.omega;
  bool persists = false;
  double after = slip.reach;                // the slipping amplitude after a failed arc
  double swing2 = slip.reach * slip.reach;  // the arc's amplitude squared at its turning point
  if (slip.x_b > 0.0) {
    const double gain = slip_arc_energy_gain(slip.law, slip.plate, slip.surface_speed);
    const double kick = omega2 * slip.x_b * slip.x_b;
    persists = kick + 2.0 * gain >= 0.0;
    swing2 = slip.x_b * slip.x_b + slip.reach * slip.reach + gain / omega2;
    after = std::sqrt(std::max(slip.reach * slip.reach + (kick + 2.0 * gain) / omega2, 0.0));
  }
  if (!persists && after > 0.0) persists = slip.rate(after) >= 0.0;
  if (persists) {
    if (std::sqrt(std::max(swing2, 0.0)) >= slip.tipping) {
      out.regime = Regime::kTips;
      out.tip_time = out.stick_time;
      return;
    }
    out.regime = Regime::kStickSlip;
    return;
  }
  const std::optional<double> root =
      after > 0.0 ? slip.first_root(after, 1e-4 * after) : std::nullopt;
  if (root && slip.rate(*root * 0.999) > 0.0) {
    out.settled_amplitude = root;
    out.regime = Regime::kOscillates;
    return;
  }
  out.regime = Regime::kDecays;
}

// A slip-dependent law, the plate slipping throughout its first cycle (A < v_r / Omega).
void slipping_start(const SlipDependentCase& slip, double amplitude, double horizon,
                    double tolerance, FrictionRegimePrediction& out) {
  const double g = out.growth_rate;
  if (g == 0.0) {
    out.regime = Regime::kOscillates;
    return;
  }
  const double ceiling = std::min(slip.reach, slip.tipping);
  const std::optional<double> root =
      g > 0.0 ? slip.first_root(amplitude, ceiling) : slip.first_root(amplitude, 1e-4 * amplitude);
  const double changed = amplitude * (g > 0.0 ? 1.0 + tolerance : 1.0 - tolerance);
  const bool changes_in_horizon = (!root || (g > 0.0 ? changed < *root : changed > *root)) &&
                                  slip.travel_time(amplitude, changed) <= horizon;
  if (root) {
    out.settled_amplitude = root;
    const bool moving = std::isfinite(horizon) && changes_in_horizon;
    out.regime = moving ? (g > 0.0 ? Regime::kGrows : Regime::kDecays) : Regime::kOscillates;
    return;
  }
  if (g < 0.0) {
    out.regime = changes_in_horizon ? Regime::kDecays : Regime::kOscillates;
    return;
  }
  const double time = slip.travel_time(amplitude, ceiling);
  if (slip.tipping <= slip.reach) {
    out.tip_time = time;
    if (time <= horizon) {
      out.regime = Regime::kTips;
      return;
    }
  } else {
    out.stick_time = time;
    if (time <= horizon) {
      after_stick(slip, out);
      return;
    }
  }
  out.regime = changes_in_horizon ? Regime::kGrows : Regime::kOscillates;
}

}  // namespace

FrictionRegimePrediction predict_friction_regime(const FrictionLaw& law,
                                                 const PlateOnRollers& plate, double surface_speed,
                                                 double amplitude, double horizon,
                                                 double steady_tolerance) {
  check_plate(plate);
  require_domain(
      std::isfinite(amplitude) && amplitude > 0.0,
      describe("the amplitude A must be a finite positive number, got ", amplitude, " m"));
  require_domain(!std::isnan(horizon) && horizon > 0.0,
                 describe("the horizon must be positive (or infinite), got ", horizon, " s"));
  require_domain(
      std::isfinite(steady_tolerance) && steady_tolerance > 0.0 && steady_tolerance < 1.0,
      describe("the steady tolerance must be a fraction in (0, 1), got ", steady_tolerance));
  FrictionRegimePrediction out;
  const double mu = effective_mu(law, surface_speed);
  out.break_offset = stick_break_offset(law, plate, surface_speed);
  out.tipping_offset = 0.5 * plate.spacing - mu * plate.h_c;
  if (!has_restoring_force(plate.spacing, mu, plate.h_c)) {
    out.regime = Regime::kNoRestoringForce;
    return out;
  }
  out.motion = linearised_motion(law, plate, surface_speed);
  const SlipDependentCase slip{law,
                               plate,
                               surface_speed,
                               out.motion.omega,
                               surface_speed / out.motion.omega,
                               out.tipping_offset,
                               out.break_offset};
  out.margin = slip.reach / amplitude;
  if (amplitude >= out.tipping_offset) {
    out.regime = Regime::kTips;
    out.tip_time = 0.0;
    return out;
  }

  if (!law.depends_on_slip()) {
    // Coulomb: the amplitude is conserved while slipping; a plate that reaches v_r sticks once
    // and then runs the stick-slip (or clipped) cycle.
    if (out.margin > 1.0) {
      out.regime = Regime::kOscillates;
      return out;
    }
    out.stick_time = std::asin(out.margin) / out.motion.omega;
    if (std::hypot(out.break_offset, slip.reach) >= out.tipping_offset) {
      out.regime = Regime::kTips;
      out.tip_time = out.stick_time;
      return out;
    }
    out.cycle = stick_slip_cycle(law, plate, surface_speed);
    out.regime = out.cycle->clipped ? Regime::kClipped : Regime::kStickSlip;
    return out;
  }

  if (out.margin <= 1.0) {
    out.stick_time = std::asin(out.margin) / out.motion.omega;
    after_stick(slip, out);
    return out;
  }
  out.growth_rate = slip.rate(amplitude);
  slipping_start(slip, amplitude, horizon, steady_tolerance, out);
  return out;
}

}  // namespace fl
