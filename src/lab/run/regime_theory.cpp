#include "lab/run/regime_theory.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/analytic_model.hpp"

namespace fl {
namespace {

// The closed forms' numbers behind a prediction, in a few words.
std::string explain(const FrictionRegimePrediction& p, double amplitude, double tipping) {
  switch (p.regime) {
    case Regime::kClipped:
      return fmt::format(
          "slip margin {:.3f} < 1: the plate reaches the rollers' speed after {:.3f} s, and its "
          "amplitude is clipped to v_r / Omega = {:.2f} mm",
          p.margin, p.stick_time.value_or(0.0), p.cycle ? p.cycle->amplitude * 1e3 : 0.0);
    case Regime::kStickSlip:
      if (p.cycle)
        return fmt::format(
            "slip margin {:.3f} < 1 and mu_s > mu_k: a stick-slip cycle of period {:.4f} s and "
            "amplitude {:.2f} mm (sticks of {:.4f} s, break at x_b = {:.2f} mm)",
            p.margin, p.cycle->period, p.cycle->amplitude * 1e3, p.cycle->stick_duration,
            p.break_offset * 1e3);
      return fmt::format(
          "the plate reaches the rollers' speed after {:.3f} s and the slip arcs keep bringing it "
          "back (break at x_b = {:.2f} mm)",
          p.stick_time.value_or(0.0), p.break_offset * 1e3);
    case Regime::kGrows:
    case Regime::kDecays:
      return fmt::format(
          "mu'(v_r) = {:+.3g} s/m: the amplitude's averaged e-folding rate is {:+.4g} /s "
          "(linearised {:+.4g} /s)",
          p.motion.slope, p.growth_rate, p.motion.gamma);
    case Regime::kTips:
      return fmt::format("the amplitude reaches l/2 - mu h_c = {:.2f} mm after {:.3f} s",
                         tipping * 1e3, p.tip_time.value_or(0.0));
    default:
      break;
  }
  if (p.settled_amplitude)
    return fmt::format("slip margin {:.2f}; the amplitude settles on the slip cycle of {:.2f} mm",
                       p.margin, *p.settled_amplitude * 1e3);
  return fmt::format("restoring, below tipping ({:.1f} of {:.1f} mm), slip margin {:.2f}",
                     amplitude * 1e3, tipping * 1e3, p.margin);
}

}  // namespace

TheoryRegime regime_from_theory(const CompiledRig& rig) {
  const double l = rig.contact_spacing;  // l, moved by the rollers' rolling resistance
  const double mu = rig.friction.mu_k;
  const double h_c = rig.plate.h_c;
  if (rig.rollers.sense == RollerSense::kOutward)
    return {Regime::kNoRestoringForce, "the rollers turn outward: friction pushes the plate away",
            std::nullopt};
  if (!rig.restoring)
    return {Regime::kNoRestoringForce,
            fmt::format("l - 2 mu_k h_c = {:.2f} mm <= 0", (l - 2.0 * mu * h_c) * 1e3),
            std::nullopt};
  const double amplitude = rig.amplitude_initial;
  if (amplitude <= 0.0)
    return {Regime::kOscillates, "the plate rests at the centre (zero amplitude)", std::nullopt};
  const double tipping = *rig.tipping_amplitude;
  if (amplitude > tipping)
    return {Regime::kTips,
            fmt::format("amplitude {:.2f} mm > l/2 - mu_k h_c = {:.2f} mm", amplitude * 1e3,
                        tipping * 1e3),
            std::nullopt};
  // The rollers' speed: set (ideal drive), or the motor's under the plate's friction load.
  // A ramped ideal drive: its slowest speed over the run, where the plate is likeliest to stick.
  double roller_speed =
      rig.roller_speed_ramp
          ? std::min(rig.roller_speed_ramp->smallest(0.0, rig.world.duration),
                     rig.roller_speed_ramp_roller_1->smallest(0.0, rig.world.duration))
          : std::min(rig.rollers.speed, rig.rollers.speed_roller_1.value_or(rig.rollers.speed));
  if (rig.drive) {
    const MotorDesc& motor = rig.drive->parts.motor;
    if (!rig.drive->roller_speed_loaded)
      return {Regime::kSticks,
              fmt::format("the motor stalls: the plate's friction needs {:.3g} N m at the motor, "
                          "more than its {:.3g} N m at {:.0f} % duty",
                          rig.drive->stall_load_torque, motor.duty * motor.stall_torque,
                          100.0 * motor.duty),
              std::nullopt};
    roller_speed = *rig.drive->roller_speed_loaded;
  }
  if (roller_speed <= 0.0)
    return {Regime::kSticks, "the rollers stand still: friction holds the plate", std::nullopt};
  const PlateOnRollers plate{l, h_c, rig.gravity_normal};
  try {
    FrictionRegimePrediction p = predict_friction_regime(
        rig.friction, plate, roller_speed * std::min(rig.roller_radii[0], rig.roller_radii[1]),
        amplitude, rig.world.duration);
    // On a tilted rig the slope's pull moves where a stick breaks, unevenly for the two rollers:
    // the level rig's stick-slip cycle is not this one's (a clipped one, mu_s = mu_k, still is,
    // about x_eq: docs/physics.md).
    if (rig.contact_tilt != 0.0 && p.regime == Regime::kStickSlip && p.cycle) {
      p.cycle.reset();
      return {p.regime,
              "the plate reaches the rollers' speed and mu_s > mu_k: a stick-slip cycle, whose "
              "closed form is a level rig's only",
              p};
    }
    return {p.regime, explain(p, amplitude, p.tipping_offset), p};
  } catch (const DomainError& e) {
    // A law the closed forms refuse here (the linearised motion creeps instead of oscillating,
    // or a stick-slip cycle that would reach the tipping offset): the coulomb test on A omega.
    const double margin = roller_speed / *rig.slip_threshold;
    return {margin < 1.0 ? Regime::kClipped : Regime::kOscillates,
            fmt::format("the friction law's closed forms do not apply ({}); slip margin {:.3f}",
                        e.what(), margin),
            std::nullopt};
  }
}

}  // namespace fl
