#include "lab/regime_theory.hpp"

#include <fmt/format.h>

#include "core/analytic_model.hpp"

namespace fl {

TheoryRegime regime_from_theory(const Scene& s) {
  const double l = s.rollers.spacing;
  const double mu = s.friction.mu_k;
  const double h_c = plate_mass(s).h_c;
  if (s.rollers.sense == RollerSense::kOutward)
    return {"no restoring force", "the rollers turn outward: friction pushes the plate away"};
  if (!has_restoring_force(l, mu, h_c))
    return {"no restoring force",
            fmt::format("l - 2 mu_k h_c = {:.2f} mm <= 0", (l - 2.0 * mu * h_c) * 1e3)};
  const double amplitude = initial_amplitude(s, mu);
  if (amplitude <= 0.0) return {"oscillates", "the plate rests at the centre (zero amplitude)"};
  const double tipping = tipping_amplitude(l, mu, h_c);
  if (amplitude > tipping)
    return {"tips", fmt::format("amplitude {:.2f} mm > l/2 - mu_k h_c = {:.2f} mm", amplitude * 1e3,
                                tipping * 1e3)};
  // The rollers' speed: set (ideal drive), or the motor's under the plate's friction load: both
  // rollers slip against the plate, taking mu_k m g a between them, G times that at the motor.
  double roller_speed = s.rollers.speed;
  if (s.drive) {
    const MotorDesc& motor = s.drive->motor;
    const double ratio = gearbox_ratio(*s.drive);
    const double load = mu * plate_mass(s).mass * s.world.gravity * s.rollers.radius;
    const double share = motor.duty - load * ratio / motor.stall_torque;
    if (share <= 0.0)
      return {"sticks",
              fmt::format("the motor stalls: the plate's friction needs {:.3g} N m at the motor, "
                          "more than its {:.3g} N m at {:.0f} % duty",
                          load * ratio, motor.duty * motor.stall_torque, 100.0 * motor.duty)};
    roller_speed = ratio * motor.no_load_speed * share;
  }
  const double margin =
      slip_margin(roller_speed, s.rollers.radius, amplitude, l, mu, h_c, s.world.gravity);
  if (margin < 1.0)
    return {"sticks",
            fmt::format("slip margin {:.3f} < 1 (roller surface speed below A omega)", margin)};
  return {"oscillates",
          fmt::format("restoring, below tipping ({:.1f} of {:.1f} mm), slip margin {:.2f}",
                      amplitude * 1e3, tipping * 1e3, margin)};
}

}  // namespace fl
