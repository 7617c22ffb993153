#include "core/friction_regime.hpp"

#include <cmath>
#include <string>

#include "core/analytic_model.hpp"
#include "core/describe.hpp"

namespace fl {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw DomainError(message);
}

}  // namespace

const char* friction_regime_name(FrictionRegime regime) {
  switch (regime) {
    case FrictionRegime::kFullSlip:
      return "full slip";
    case FrictionRegime::kGrows:
      return "grows";
    case FrictionRegime::kDecays:
      return "decays";
    case FrictionRegime::kClipped:
      return "clipped";
    case FrictionRegime::kStickSlip:
      return "stick-slip";
    case FrictionRegime::kTips:
      return "tips";
    case FrictionRegime::kNoRestoringForce:
      return "no restoring force";
  }
  return "unknown";
}

FrictionRegimePrediction predict_friction_regime(const FrictionLaw& law,
                                                 const PlateOnRollers& plate, double surface_speed,
                                                 double amplitude, double horizon,
                                                 double steady_tolerance) {
  check_plate(plate);
  require(std::isfinite(amplitude) && amplitude > 0.0,
          describe("the amplitude A must be a finite positive number, got ", amplitude, " m"));
  require(!std::isnan(horizon) && horizon > 0.0,
          describe("the horizon must be positive (or infinite), got ", horizon, " s"));
  require(
      std::isfinite(steady_tolerance) && steady_tolerance > 0.0,
      describe("the steady tolerance must be a finite positive fraction, got ", steady_tolerance));
  FrictionRegimePrediction out;
  const double mu = effective_mu(law, surface_speed);
  out.break_offset = stick_break_offset(law, plate, surface_speed);
  out.tipping_offset = 0.5 * plate.spacing - mu * plate.h_c;
  if (!has_restoring_force(plate.spacing, mu, plate.h_c)) {
    out.regime = FrictionRegime::kNoRestoringForce;
    return out;
  }
  out.motion = linearised_motion(law, plate, surface_speed);
  const double omega = out.motion.omega;
  const double gamma = out.motion.gamma;
  const double reach = surface_speed / omega;
  out.margin = reach / amplitude;
  if (amplitude >= out.tipping_offset) {
    out.regime = FrictionRegime::kTips;
    out.tip_time = 0.0;
    return out;
  }

  if (out.margin <= 1.0) {
    // Reaches v_r within its first cycle, and a plate that reaches v_r sticks.
    out.stick_time = std::asin(out.margin) / omega;
    const double settled = std::hypot(out.break_offset, reach);
    if (settled >= out.tipping_offset) {
      out.regime = FrictionRegime::kTips;
      out.tip_time = 0.0;
      return out;
    }
    if (!law.depends_on_slip()) {
      out.cycle = stick_slip_cycle(law, plate, surface_speed);
      out.regime = out.cycle->clipped ? FrictionRegime::kClipped : FrictionRegime::kStickSlip;
    } else {
      // After the stick, the speed's extremes change by exp(gamma T / 2) per half period: a
      // rising law never brings the plate back to a roller's speed, a falling one always does.
      out.regime = gamma < 0.0 ? FrictionRegime::kDecays : FrictionRegime::kStickSlip;
    }
    return out;
  }

  if (gamma > 0.0) {
    const double stick = std::log(out.margin) / gamma;
    const double tip = std::log(out.tipping_offset / amplitude) / gamma;
    if (tip <= stick) {  // reach = v_r / Omega at or beyond the tipping offset
      out.tip_time = tip;
      if (tip <= horizon) {
        out.regime = FrictionRegime::kTips;
        return out;
      }
    } else {
      out.stick_time = stick;
      if (stick <= horizon) {
        out.regime = FrictionRegime::kStickSlip;
        return out;
      }
    }
    out.regime = std::expm1(gamma * horizon) > steady_tolerance ? FrictionRegime::kGrows
                                                                : FrictionRegime::kFullSlip;
    return out;
  }
  if (gamma < 0.0) {
    out.regime = -std::expm1(gamma * horizon) > steady_tolerance ? FrictionRegime::kDecays
                                                                 : FrictionRegime::kFullSlip;
    return out;
  }
  out.regime = FrictionRegime::kFullSlip;
  return out;
}

}  // namespace fl
