#include "core/stick_slip_cycle.hpp"

#include <cmath>
#include <string>

#include "core/analytic_model.hpp"
#include "core/domain_check.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

void require_no_slip_dependence(const FrictionLaw& law) {
  require_domain(
      !law.depends_on_slip(),
      "no closed-form stick-slip cycle for a slip-dependent law (stribeck with mu_s > mu_k "
      "or beta != 0); use a coulomb law");
}

}  // namespace

StickSlipCycle stick_slip_cycle(const FrictionLaw& law, const PlateOnRollers& plate,
                                double surface_speed) {
  require_no_slip_dependence(law);
  StickSlipCycle out;
  out.omega = sliding_angular_frequency(law, plate, surface_speed);
  out.break_offset = stick_break_offset(law, plate, surface_speed);
  const double reach = surface_speed / out.omega;
  out.amplitude = std::hypot(out.break_offset, reach);
  const double tipping = tipping_amplitude(plate.spacing, law.mu_k, plate.h_c);
  require_domain(out.amplitude < tipping,
                 describe("the stick-slip cycle's amplitude ", out.amplitude,
                          " m reaches the tipping offset l/2 - mu_k h_c = ", tipping, " m"));
  out.stick_duration = 2.0 * out.break_offset / surface_speed;
  out.slip_duration = 2.0 / out.omega * std::atan2(surface_speed, out.omega * out.break_offset);
  out.period = 2.0 * (out.stick_duration + out.slip_duration);
  out.clipped = out.break_offset == 0.0;
  return out;
}

FirstStick first_stick(const FrictionLaw& law, const PlateOnRollers& plate, double surface_speed,
                       double amplitude) {
  require_no_slip_dependence(law);
  const double omega = sliding_angular_frequency(law, plate, surface_speed);
  const double reach = surface_speed / omega;
  require_domain(std::isfinite(amplitude) && amplitude > reach,
                 describe("an oscillation of amplitude ", amplitude,
                          " m never reaches the rollers' speed (it needs more than v_r / Omega = ",
                          reach, " m)"));
  const double tipping = tipping_amplitude(plate.spacing, law.mu_k, plate.h_c);
  require_domain(amplitude < tipping,
                 describe("the amplitude ", amplitude,
                          " m reaches the tipping offset l/2 - mu_k h_c = ", tipping, " m"));
  FirstStick out;
  out.time_to_stick = std::asin(reach / amplitude) / omega;
  out.entry_offset = -std::sqrt((amplitude - reach) * (amplitude + reach));
  out.duration = (stick_break_offset(law, plate, surface_speed) - out.entry_offset) / surface_speed;
  return out;
}

}  // namespace fl
