#include "lab/run/summary_text.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/units.hpp"

namespace fl {
namespace {

using Text = std::optional<std::string>;
using S = const RunSummary&;

// A measured number in a unit, or "not measured".
std::string value(const std::optional<double>& v, double scale, const char* unit) {
  return v ? fmt::format("{:.5g} {}", *v * scale, unit) : std::string("not measured");
}

// A closed form's number beside a measured one, when theory has one.
std::string theory(const std::optional<double>& v, double scale, const char* unit) {
  return v ? fmt::format(" (theory {:.5g} {})", *v * scale, unit) : std::string();
}

// Whether the estimator's statistics are the run's headline (a harmonic run with a sensor).
bool estimator_headline(S s) {
  return s.estimator && s.harmonic();
}

Text gearbox(S s) {
  if (!s.drive) return std::nullopt;
  const DriveReport& d = *s.drive;
  // The ratio and senses are measured over the steps in which the motor and both rollers turned,
  // and the line says when that was only part of the run.
  const std::string speeds =
      fmt::format("rollers at {:+.0f} and {:+.0f} rpm", d.roller_speeds[0] * kRpmPerRadPerSecond,
                  d.roller_speeds[1] * kRpmPerRadPerSecond);
  if (!d.speed_ratio)
    return fmt::format("{}: the train never turned, no ratio measured (design {:.3f})", speeds,
                       d.gearbox_ratio);
  const std::string share =
      d.turning_fraction < 1.0
          ? fmt::format(" while turning ({:.1f} % of the run)", 100.0 * d.turning_fraction)
          : std::string();
  return fmt::format("{}: {:.4f} x the motor{} (design {:.3f}, worst step {:.2e} off), senses {}",
                     speeds, *d.speed_ratio, share, d.gearbox_ratio, *d.speed_ratio_error,
                     *d.senses_opposite ? "opposite" : "NOT opposite");
}

Text warming(S s) {
  if (!s.warming) return std::nullopt;
  const WarmingReport& w = *s.warming;
  return fmt::format(
      "{:.0f} K -> {:.0f} K at the end ({:.0f} K room, tau {:.3g} s after {:.3g} s cold): mu_k "
      "{:.4g} -> {:.4g} (linear in T between {:.4g} and {:.4g})",
      w.start_temperature, w.end_temperature, w.room_temperature, w.time_constant, w.hold,
      w.mu_k_start, w.mu_k_end, w.mu_k_start, w.mu_k_room);
}

Text warming_windows(S s) {
  if (!s.warming) return std::nullopt;
  const WarmingReport& w = *s.warming;
  const auto window = [&](const std::optional<WarmingWindow>& v) {
    if (!v) return std::string("none");
    return fmt::format("{:.4f} ({:+.1f} %, {} periods)", v->mu_k,
                       100.0 * (v->mu_k / w.mu_k_cold_paper_formula - 1.0), v->periods);
  };
  return fmt::format(
      "first 10 periods {}, first 30 s {}, whole run {}; {:.4f} from rollers that stay at {:.0f} K "
      "(the paper's formula)",
      window(w.first_10_periods), window(w.first_30_s), window(w.whole_run),
      w.mu_k_cold_paper_formula, w.start_temperature);
}

Text runout(S s) {
  if (!s.runout || !s.runout_threshold) return std::nullopt;
  const bool above = *s.runout > *s.runout_threshold;
  return fmt::format(
      "{:.3f} mm, {} the {:.3f} mm above which theory has the plate hop (at its starting turning "
      "points, {:.0f} rpm){}",
      *s.runout * 1e3, above ? "above" : "below", *s.runout_threshold * 1e3,
      s.roller_speed * kRpmPerRadPerSecond,
      s.jumps ? fmt::format(": {} jumps, the highest {:.3f} mm", *s.jumps,
                            s.highest_jump.value_or(0.0) * 1e3)
              : std::string(": no jump"));
}

Text oscillation_centre(S s) {
  // A plate oscillating off the rollers' midpoint (a tilted rig's, rollers at different speeds):
  // where, beside theory's x_eq.
  const bool off_centre = s.tilt != 0.0 || s.oscillation_centre_theory.value_or(0.0) != 0.0;
  if (!off_centre || !s.oscillation_centre) return std::nullopt;
  return fmt::format(
      "{:+.3f} mm (theory {}{})", *s.oscillation_centre * 1e3,
      s.oscillation_centre_theory ? fmt::format("{:+.3f} mm", *s.oscillation_centre_theory * 1e3)
                                  : std::string("none"),
      s.tilt != 0.0 ? fmt::format(", the rig tilted {:+.2f} deg", s.tilt * 180.0 / kPi)
                    : std::string());
}

Text thick_plate(S s) {
  if (!s.period_thick) return std::nullopt;
  std::string errors;
  if (s.period)
    errors += fmt::format("  (estimator {:+.4f} %", 100.0 * (*s.period / *s.period_thick - 1.0));
  if (s.period_trajectory)
    errors += fmt::format("{}trajectory {:+.4f} %)", s.period ? ", " : "  (",
                          100.0 * (*s.period_trajectory / *s.period_thick - 1.0));
  else if (s.period)
    errors += ")";
  return fmt::format("{:.6f} s{}", *s.period_thick, errors);
}

Text rollers(S s) {
  const std::string speeds =
      std::fabs(s.roller_speed_1 - s.roller_speed) > 1e-9 * std::fabs(s.roller_speed)
          ? fmt::format("{:.0f} rpm (roller 0), {:.0f} rpm (roller 1)",
                        s.roller_speed * kRpmPerRadPerSecond,
                        s.roller_speed_1 * kRpmPerRadPerSecond)
          : fmt::format("{:.0f} rpm", s.roller_speed * kRpmPerRadPerSecond);
  return fmt::format("{}, slip margin {:.2f}", speeds, s.slip_margin);
}

// What the run shows: its regime and what stopped, clipped or warmed it.
std::vector<SummaryLine> regime_lines() {
  return {
      {"regime",
       {"regime", "regime_since_s", "regime_evidence"},
       [](S s) -> Text {
         return fmt::format(
             "{}{}: {}", regime_name(s.regime),
             s.regime_since > 0.0 ? fmt::format(" since t = {:.4f} s", s.regime_since) : "",
             s.regime_evidence);
       },
       true},
      {"STOPPED", {"failure"}, [](S s) -> Text { return s.failure; }},
      // The regime's own numbers, beside the closed forms' (not measured where they were not).
      {"clipped",
       {"clip_time_s", "amplitude_before_clip_m", "amplitude_clipped_m",
        "amplitude_clipped_theory_m"},
       [](S s) -> Text {
         if (!s.clip_time) return std::nullopt;
         return fmt::format("at t = {:.4f} s: amplitude {} -> {}{}", *s.clip_time,
                            value(s.amplitude_before_clip, 1e3, "mm"),
                            value(s.amplitude_clipped, 1e3, "mm"),
                            theory(s.amplitude_clipped_theory, 1e3, "mm"));
       }},
      {"stick-slip cycle",
       {"stick_slip_period_s", "stick_slip_period_theory_s", "stick_slip_amplitude_m",
        "stick_slip_amplitude_theory_m", "stick_duration_s", "stick_duration_theory_s"},
       [](S s) -> Text {
         if (s.regime != Regime::kStickSlip) return std::nullopt;
         return fmt::format(
             "T = {}{}, amplitude {}{}, sticks of {}{}", value(s.stick_slip_period, 1.0, "s"),
             theory(s.stick_slip_period_theory, 1.0, "s"), value(s.stick_slip_amplitude, 1e3, "mm"),
             theory(s.stick_slip_amplitude_theory, 1e3, "mm"), value(s.stick_duration, 1.0, "s"),
             theory(s.stick_duration_theory, 1.0, "s"));
       }},
      {"amplitude e-folding",
       {"growth_rate_per_s", "growth_rate_theory_per_s", "e_folding_time_s"},
       [](S s) -> Text {
         if (!s.growth_rate) return std::nullopt;
         return fmt::format("{:+.5g} /s{}, every {:.4g} s", *s.growth_rate,
                            theory(s.growth_rate_theory, 1.0, "/s"),
                            s.e_folding_time.value_or(0.0));
       }},
      {"solver iterations",
       {"solver_iterations", "solver_iterations_raised"},
       [](S s) -> Text {
         if (!s.solver_iterations_raised) return std::nullopt;
         return fmt::format("{}, raised {}", s.solver_iterations, *s.solver_iterations_raised);
       }},
      {"INTERRUPTED",
       {"interrupted_at_s"},
       [](S s) -> Text {
         if (!s.interrupted_at) return std::nullopt;
         return fmt::format("at t = {:.3f} s: what follows is the run up to there",
                            *s.interrupted_at);
       }},
      {"period", {"period_withheld"}, [](S s) -> Text { return s.period_withheld; }},
      {"sensor clock",
       {"sensor_clock_error", "clock_mu_k_bias"},
       [](S s) -> Text {
         if (!s.clock_error) return std::nullopt;
         return fmt::format(
             "runs {:+.4g} % fast: every period reads {:+.4g} %, mu_k {:+.4g} %; time a known "
             "interval on the board to calibrate it away (docs/estimator.md)",
             100.0 * *s.clock_error, 100.0 * *s.clock_error,
             100.0 * (1.0 / ((1.0 + *s.clock_error) * (1.0 + *s.clock_error)) - 1.0));
       }},
      {"run-out", {"runout_m", "runout_threshold_m", "jumps", "highest_jump_m"}, runout},
      {"rollers warming", {"warming"}, warming},
      {"mu_k a student gets", {"warming"}, warming_windows},
      {"WARNING", {"estimator_disagreement"}, [](S s) -> Text { return s.estimator_disagreement; }},
  };
}

// What the run measured: the rig, the periods, mu_k, against theory and the paper.
std::vector<SummaryLine> measured_lines() {
  return {
      {"roller spacing l",
       {"spacing_m", "h_c_m", "plate_mass_kg", "mu_k_set"},
       [](S s) -> Text {
         return fmt::format("{:.2f} mm, h_c {:.2f} mm, plate {:.1f} g, mu_k set {:.4g}",
                            s.spacing * 1e3, s.h_c * 1e3, s.plate_mass * 1e3, s.mu_k_set);
       },
       true},
      {"period (Hall estimator)",
       {"period_s", "period_std_s", "periods_used", "periods_discarded"},
       [](S s) -> Text {
         if (!estimator_headline(s)) return std::nullopt;
         const EstimatorReport& e = *s.estimator;
         if (e.periods_used == 0)
           return fmt::format("none: {} pulse(s), no accepted period", e.pulses);
         return fmt::format("T = {:.5f} +- {:.5f} s (N = {}, {} discarded)", e.period, e.period_std,
                            e.periods_used, e.periods_discarded);
       }},
      {"mu_k recovered",
       {"mu_k_estimator", "mu_k_err_worst", "mu_k_err_quadrature"},
       [](S s) -> Text {
         if (!estimator_headline(s) || s.estimator->periods_used == 0) return std::nullopt;
         const EstimatorReport& e = *s.estimator;
         return fmt::format("{:.4f} +- {:.4f} (worst) +- {:.4f} (quadrature), paper's formula",
                            e.mu_k, e.mu_k_err_worst, e.mu_k_err_quadrature);
       }},
      {"conditioning",
       {"condition_period", "condition_spacing", "condition_h_c"},
       [](S s) -> Text {
         if (!(s.condition_period > 0.0 && s.harmonic())) return std::nullopt;
         return fmt::format(
             "d mu/mu = {:.3f} dT/T + {:.0f} dl/l + {:.3f} dh_c/h_c (thick formula, h_c = {:.2f} "
             "mm){}",
             s.condition_period, s.condition_spacing, s.condition_h_c, s.h_c * 1e3,
             s.condition_period < 0.5 ? ": the period hardly pins mu_k down here, h_c does" : "");
       }},
      {"mu_k through the thick formula",
       {"mu_k_recovered_thick"},
       [](S s) -> Text {
         if (!s.mu_k_recovered_thick) return std::nullopt;
         return fmt::format("(h_c = {:.2f} mm): {:.4f}", s.h_c * 1e3, *s.mu_k_recovered_thick);
       }},
      {"period (trajectory)",
       {"period_trajectory_s"},
       [](S s) -> Text {
         if (!s.period_trajectory) return std::nullopt;
         return fmt::format("{:.6f} s", *s.period_trajectory);
       }},
      {"oscillation centre",
       {"oscillation_centre_m", "oscillation_centre_theory_m", "tilt_rad"},
       oscillation_centre},
      {"sideways drift",
       {"drift_speed_m_s", "drift_speed_theory_m_s"},
       [](S s) -> Text {
         if (!s.drift_speed) return std::nullopt;
         return fmt::format(
             "{:+.3f} mm/s over the run's second half (theory {})", *s.drift_speed * 1e3,
             s.drift_speed_theory
                 ? fmt::format("{:+.3f} mm/s, v_r sin(skew/2)", *s.drift_speed_theory * 1e3)
                 : std::string("none: guide towers hold the plate, or the rollers' "
                               "surface speeds differ or change"));
       }},
      {"analytic, thin plate",
       {"period_thin_s", "error_vs_thin"},
       [](S s) -> Text {
         return fmt::format("{:.6f} s{}", s.period_thin,
                            s.period ? fmt::format("  (estimator {:+.4f} %)",
                                                   100.0 * (*s.period / s.period_thin - 1.0))
                                     : std::string());
       },
       true},
      {"analytic, thick plate",
       {"period_thick_s", "error_vs_thick", "trajectory_error_vs_thick"},
       thick_plate},
      {"the paper measured",
       {"paper"},
       [](S s) -> Text {
         if (!s.paper_period) return std::nullopt;
         return fmt::format("T = {:.{}f} +- {:.{}f} s, mu_k = {:.{}f} +- {:.{}f} ({})",
                            s.paper_period->value, s.paper_period->decimals,
                            s.paper_period->uncertainty, s.paper_period->uncertainty_decimals,
                            s.paper_mu_k->value, s.paper_mu_k->decimals, s.paper_mu_k->uncertainty,
                            s.paper_mu_k->uncertainty_decimals, s.paper_material);
       }},
      {"simulated - measured",
       {"paper", "period_s"},
       [](S s) -> Text {
         if (!s.paper_period || !s.period) return std::nullopt;
         return fmt::format("{:+.4f} s = {:+.2f} dT", *s.period - s.paper_period->value,
                            (*s.period - s.paper_period->value) / s.paper_period->uncertainty);
       }},
  };
}

// The numerics, the amplitude, the drive and what the run cost.
std::vector<SummaryLine> rig_lines() {
  return {
      {"integrator bias",
       {"predicted_integrator_bias", "time_step_s"},
       [](S s) -> Text {
         if (!s.predicted_integrator_bias) return std::nullopt;
         return fmt::format("{:+.2e} predicted at dt = {:.3g} ms, -(omega dt)^2/24",
                            *s.predicted_integrator_bias, s.time_step * 1e3);
       }},
      {"amplitude",
       {"amplitude_start_m", "amplitude_end_m", "amplitude_drift_per_period"},
       [](S s) -> Text {
         if (!s.amplitude_start || !s.amplitude_end)
           return std::string("none measured: the run reached no turning point");
         return fmt::format(
             "{:.3f} mm at start, {:.3f} mm at end{}", *s.amplitude_start * 1e3,
             *s.amplitude_end * 1e3,
             s.amplitude_drift_per_period
                 ? fmt::format(" ({:+.2e} per period)", *s.amplitude_drift_per_period)
                 : std::string());
       },
       true},
      {"motor",
       {"drive"},
       [](S s) -> Text {
         if (!s.drive) return std::nullopt;
         const DriveReport& d = *s.drive;
         return fmt::format(
             "{:.1f} rpm, {:.1f} mN m (the plate's friction takes {:.2f} mN m at the rollers)",
             d.motor_speed * kRpmPerRadPerSecond, d.motor_torque * 1e3, d.load_torque * 1e3);
       }},
      {"gearbox", {"drive"}, gearbox},
      {"rollers", {"roller_speed_rad_s", "roller_speed_1_rad_s", "slip_margin"}, rollers, true},
      {"run",
       {"duration_s", "wall_s", "real_time_factor", "steps_per_second"},
       [](S s) -> Text {
         return fmt::format("{:.2f} s simulated in {:.3f} s: {:.0f} x real time, {:.0f} steps/s",
                            s.duration, s.wall_s, s.real_time_factor, s.steps_per_second);
       },
       true},
  };
}

std::vector<SummaryLine> declare() {
  std::vector<SummaryLine> lines;
  for (auto* group : {&regime_lines, &measured_lines, &rig_lines}) {
    std::vector<SummaryLine> part = group();
    lines.insert(lines.end(), part.begin(), part.end());
  }
  return lines;
}

}  // namespace

const std::vector<SummaryLine>& summary_lines() {
  static const std::vector<SummaryLine> lines = declare();
  return lines;
}

const std::vector<TextOmission>& summary_text_omissions() {
  static const std::vector<TextOmission> omissions = {
      {"scene", "the first line names it"},
      {"seed", "the first line names it"},
      {"period_std_error_s", "the text gives the periods' spread, the paper's dT"},
      {"period_trajectory_err_s", "the trajectory's fit's own uncertainty, for a sweep's rows"},
      {"mu_k_recovered",
       "the headline mu_k: the estimator's when it gave the period (mu_k recovered); otherwise "
       "from the trajectory's period, which the text gives with the thick formula's mu_k"},
      {"mu_k_source", "the period line says so when mu_k does not come from the estimator"},
      {"regime_theory", "the regime line gives what the trajectory shows"},
      {"plate_speed_max_m_s", "the rollers line gives the slip margin it sets"},
      {"first_jump_time_s", "jumps.csv lists every jump; the run-out line counts them"},
      {"longest_jump_s", "jumps.csv lists every jump; the run-out line counts them"},
      {"min_normal_force_n", "the contact model's own check, for summary.json"},
      {"max_penetration_m", "the contact model's own check, for summary.json"},
      {"steps", "the run line gives the simulated time and the steps a second"},
  };
  return omissions;
}

std::string summary_text(const RunSummary& s) {
  std::string out = fmt::format("frictionlab run: {} (seed {})\n", s.scene, s.seed);
  for (const SummaryLine& line : summary_lines())
    if (const Text text = line.text(s)) out += fmt::format("  {:<22} {}\n", line.label, *text);
  return out;
}

}  // namespace fl
