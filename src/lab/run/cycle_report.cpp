#include "lab/run/cycle_report.hpp"

#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/friction_oscillator.hpp"
#include "core/stick_slip_cycle.hpp"
#include "core/units.hpp"

namespace fl {
namespace {

std::string cell(const std::optional<double>& v) {
  return v ? fmt::format("{}", *v) : std::string();
}

// What theory says at surface speed v_r: the largest amplitude that slips on both rollers
// throughout (v_r / Omega(mu(v_r))), and the stick-slip cycle the plate falls into once it
// reaches a roller's speed (a law without slip dependence only). Empty where a closed form has no
// meaning (no restoring force, a cycle beyond tipping, a slip-dependent law).
struct CycleTheory {
  std::optional<double> slip_limit_amplitude;
  std::optional<double> stick_slip_amplitude;
  std::optional<double> stick_slip_period;
};

CycleTheory theory_at(const CompiledRig& rig, double surface_speed) {
  CycleTheory out;
  if (!rig.restoring || !(surface_speed > 0.0)) return out;
  const PlateOnRollers plate{rig.contact_spacing, rig.plate.h_c, rig.gravity_normal};
  try {
    out.slip_limit_amplitude =
        surface_speed / sliding_angular_frequency(rig.friction, plate, surface_speed);
  } catch (const DomainError&) {
  }
  // The stick-slip cycle's closed form is a level rig's (lab/run/regime_theory.cpp).
  if (!rig.friction.depends_on_slip() &&
      (rig.contact_tilt == 0.0 || rig.friction.mu_s == rig.friction.mu_k)) {
    try {
      const StickSlipCycle cycle = stick_slip_cycle(rig.friction, plate, surface_speed);
      out.stick_slip_amplitude = cycle.amplitude;
      out.stick_slip_period = cycle.period;
    } catch (const DomainError&) {
    }
  }
  return out;
}

}  // namespace

std::string ramp_direction(const CompiledRig& rig, const CycleRecord& cycle) {
  const std::optional<Ramp>& ramp = rig.roller_speed_ramp ? rig.roller_speed_ramp : rig.duty_ramp;
  if (!ramp) return "hold";
  const double slope = ramp->slope(cycle.start + 0.5 * cycle.period);
  return slope > 0.0 ? "up" : slope < 0.0 ? "down" : "hold";
}

std::string cycles_csv(const CompiledRig& rig, const std::vector<CycleRecord>& cycles) {
  const double a = rig.rollers.radius;
  std::string out =
      "start_s,period_s,amplitude_m,x_min_m,x_max_m,roller_speed_rpm,surface_speed_m_s,ramp,"
      "stuck,stick_s,slip_limit_amplitude_m,stick_slip_amplitude_m,stick_slip_period_s\n";
  for (const CycleRecord& c : cycles) {
    const CycleTheory theory = theory_at(rig, c.surface_speed_mean);
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{},{},{},{},{},{}\n", c.start,
                   c.period, c.amplitude, c.x_min, c.x_max,
                   c.surface_speed_mean / a * kRpmPerRadPerSecond, c.surface_speed_mean,
                   ramp_direction(rig, c), c.stuck() ? "true" : "false", c.stick_duration,
                   cell(theory.slip_limit_amplitude), cell(theory.stick_slip_amplitude),
                   cell(theory.stick_slip_period));
  }
  return out;
}

}  // namespace fl
