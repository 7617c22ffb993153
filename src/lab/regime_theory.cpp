#include "lab/regime_theory.hpp"

#include <fmt/format.h>

namespace fl {

TheoryRegime regime_from_theory(const CompiledRig& rig) {
  const Scene& s = rig.scene;
  const double l = rig.spacing;
  const double mu = rig.mu_k;
  const double h_c = rig.plate.h_c;
  if (s.rollers.sense == RollerSense::kOutward)
    return {Regime::kNoRestoringForce, "the rollers turn outward: friction pushes the plate away"};
  if (!rig.restoring)
    return {Regime::kNoRestoringForce,
            fmt::format("l - 2 mu_k h_c = {:.2f} mm <= 0", (l - 2.0 * mu * h_c) * 1e3)};
  const double amplitude = rig.amplitude_initial;
  if (amplitude <= 0.0)
    return {Regime::kOscillates, "the plate rests at the centre (zero amplitude)"};
  const double tipping = *rig.tipping_amplitude;
  if (amplitude > tipping)
    return {Regime::kTips, fmt::format("amplitude {:.2f} mm > l/2 - mu_k h_c = {:.2f} mm",
                                       amplitude * 1e3, tipping * 1e3)};
  // The rollers' speed: set (ideal drive), or the motor's under the plate's friction load.
  double roller_speed = s.rollers.speed;
  if (rig.drive) {
    const MotorDesc& motor = s.drive->motor;
    if (!rig.drive->roller_speed_loaded)
      return {Regime::kSticks,
              fmt::format("the motor stalls: the plate's friction needs {:.3g} N m at the motor, "
                          "more than its {:.3g} N m at {:.0f} % duty",
                          rig.drive->stall_load_torque, motor.duty * motor.stall_torque,
                          100.0 * motor.duty)};
    roller_speed = *rig.drive->roller_speed_loaded;
  }
  const double margin = roller_speed / *rig.slip_threshold;
  if (margin < 1.0)
    return {Regime::kSticks,
            fmt::format("slip margin {:.3f} < 1 (roller surface speed below A omega)", margin)};
  return {Regime::kOscillates,
          fmt::format("restoring, below tipping ({:.1f} of {:.1f} mm), slip margin {:.2f}",
                      amplitude * 1e3, tipping * 1e3, margin)};
}

}  // namespace fl
