#include "lab/run/run_outputs.hpp"

#include <cmath>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "core/units.hpp"
#include "io/atomic_file.hpp"
#include "lab/run/cycle_report.hpp"
#include "lab/run/summary_fields.hpp"

namespace fl {

namespace {

// The gear train's line: the ratio and senses are measured over the steps in which the motor and
// both rollers turned, and the line says when that was only part of the run.
std::string gearbox_line(const DriveReport& d) {
  const std::string speeds = fmt::format(
      "  gearbox                rollers at {:+.0f} and {:+.0f} rpm",
      d.roller_speeds[0] * kRpmPerRadPerSecond, d.roller_speeds[1] * kRpmPerRadPerSecond);
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

}  // namespace

std::string summary_text(const RunSummary& s) {
  std::string out;
  const auto line = [&out](const std::string& text) { out += text + "\n"; };
  line(fmt::format("frictionlab run: {} (seed {})", s.scene, s.seed));
  line(fmt::format("  regime                 {}{}: {}", regime_name(s.regime),
                   s.regime_since > 0.0 ? fmt::format(" since t = {:.4f} s", s.regime_since) : "",
                   s.regime_evidence));
  if (s.failure) line(fmt::format("  STOPPED                {}", *s.failure));
  // The regime's own numbers, beside the closed forms' (null where a number was not measured).
  const auto value = [](const std::optional<double>& v, double scale, const char* unit) {
    return v ? fmt::format("{:.5g} {}", *v * scale, unit) : std::string("not measured");
  };
  const auto theory = [](const std::optional<double>& v, double scale, const char* unit) {
    return v ? fmt::format(" (theory {:.5g} {})", *v * scale, unit) : std::string();
  };
  if (s.clip_time)
    line(fmt::format("  clipped                at t = {:.4f} s: amplitude {} -> {}{}", *s.clip_time,
                     value(s.amplitude_before_clip, 1e3, "mm"),
                     value(s.amplitude_clipped, 1e3, "mm"),
                     theory(s.amplitude_clipped_theory, 1e3, "mm")));
  if (s.regime == Regime::kStickSlip)
    line(fmt::format(
        "  stick-slip cycle       T = {}{}, amplitude {}{}, sticks of {}{}",
        value(s.stick_slip_period, 1.0, "s"), theory(s.stick_slip_period_theory, 1.0, "s"),
        value(s.stick_slip_amplitude, 1e3, "mm"), theory(s.stick_slip_amplitude_theory, 1e3, "mm"),
        value(s.stick_duration, 1.0, "s"), theory(s.stick_duration_theory, 1.0, "s")));
  if (s.growth_rate)
    line(fmt::format("  amplitude e-folding    {:+.5g} /s{}, every {:.4g} s", *s.growth_rate,
                     theory(s.growth_rate_theory, 1.0, "/s"), s.e_folding_time.value_or(0.0)));
  if (s.solver_iterations_raised)
    line(fmt::format("  solver iterations      {}, raised {}", s.solver_iterations,
                     *s.solver_iterations_raised));
  if (s.interrupted_at)
    line(
        fmt::format("  INTERRUPTED            at t = {:.3f} s: what follows is the run up to there",
                    *s.interrupted_at));
  if (s.period_withheld) line(fmt::format("  period                 {}", *s.period_withheld));
  if (s.clock_error)
    line(fmt::format(
        "  sensor clock           runs {:+.4g} % fast: every period reads {:+.4g} %, mu_k {:+.4g} "
        "%; time a known interval on the board to calibrate it away (docs/estimator.md)",
        100.0 * *s.clock_error, 100.0 * *s.clock_error,
        100.0 * (1.0 / ((1.0 + *s.clock_error) * (1.0 + *s.clock_error)) - 1.0)));
  if (s.runout && s.runout_threshold) {
    const bool above = *s.runout > *s.runout_threshold;
    line(fmt::format(
        "  run-out                {:.3f} mm, {} the {:.3f} mm above which theory has the plate hop "
        "(at its starting turning points, {:.0f} rpm){}",
        *s.runout * 1e3, above ? "above" : "below", *s.runout_threshold * 1e3,
        s.roller_speed * kRpmPerRadPerSecond,
        s.jumps ? fmt::format(": {} jumps, the highest {:.3f} mm", *s.jumps,
                              s.highest_jump.value_or(0.0) * 1e3)
                : std::string(": no jump")));
  }
  if (s.warming) {
    const WarmingReport& w = *s.warming;
    line(
        fmt::format("  rollers warming        {:.0f} K -> {:.0f} K at the end ({:.0f} K room, tau "
                    "{:.3g} s after "
                    "{:.3g} s cold): mu_k {:.4g} -> {:.4g} (linear in T between {:.4g} and {:.4g})",
                    w.start_temperature, w.end_temperature, w.room_temperature, w.time_constant,
                    w.hold, w.mu_k_start, w.mu_k_end, w.mu_k_start, w.mu_k_room));
    const auto window = [&](const std::optional<WarmingWindow>& v) {
      if (!v) return std::string("none");
      return fmt::format("{:.4f} ({:+.1f} %, {} periods)", v->mu_k,
                         100.0 * (v->mu_k / w.mu_k_cold_paper_formula - 1.0), v->periods);
    };
    line(
        fmt::format("  mu_k a student gets    first 10 periods {}, first 30 s {}, whole run {}; "
                    "{:.4f} from rollers that stay at {:.0f} K (the paper's formula)",
                    window(w.first_10_periods), window(w.first_30_s), window(w.whole_run),
                    w.mu_k_cold_paper_formula, w.start_temperature));
  }
  if (s.estimator_disagreement)
    line(fmt::format("  WARNING                {}", *s.estimator_disagreement));
  line(fmt::format(
      "  roller spacing l       {:.2f} mm, h_c {:.2f} mm, plate {:.1f} g, mu_k set {:.4g}",
      s.spacing * 1e3, s.h_c * 1e3, s.plate_mass * 1e3, s.mu_k_set));
  const std::optional<double>& period = s.period;
  if (s.estimator && s.harmonic()) {
    const EstimatorReport& e = *s.estimator;
    if (e.periods_used > 0) {
      line(fmt::format("  period (Hall estimator) T = {:.5f} +- {:.5f} s (N = {}, {} discarded)",
                       e.period, e.period_std, e.periods_used, e.periods_discarded));
      line(
          fmt::format("  mu_k recovered         {:.4f} +- {:.4f} (worst) +- {:.4f} (quadrature), "
                      "paper's formula",
                      e.mu_k, e.mu_k_err_worst, e.mu_k_err_quadrature));
    } else {
      line(
          fmt::format("  period (Hall estimator) none: {} pulse(s), no accepted period", e.pulses));
    }
  }
  if (s.condition_period > 0.0 && s.harmonic())
    line(fmt::format(
        "  conditioning           d mu/mu = {:.3f} dT/T + {:.0f} dl/l + {:.3f} dh_c/h_c "
        "(thick formula, h_c = {:.2f} mm){}",
        s.condition_period, s.condition_spacing, s.condition_h_c, s.h_c * 1e3,
        s.condition_period < 0.5 ? ": the period hardly pins mu_k down here, h_c does" : ""));
  if (s.mu_k_recovered_thick)
    line(fmt::format("  mu_k through the thick formula (h_c = {:.2f} mm): {:.4f}", s.h_c * 1e3,
                     *s.mu_k_recovered_thick));
  if (s.period_trajectory)
    line(fmt::format("  period (trajectory)    {:.6f} s", *s.period_trajectory));
  // A plate oscillating off the rollers' midpoint (a tilted rig's, rollers at different speeds):
  // where, beside theory's x_eq.
  const bool off_centre = s.tilt != 0.0 || s.oscillation_centre_theory.value_or(0.0) != 0.0;
  if (off_centre && s.oscillation_centre)
    line(fmt::format(
        "  oscillation centre     {:+.3f} mm (theory {}{})", *s.oscillation_centre * 1e3,
        s.oscillation_centre_theory ? fmt::format("{:+.3f} mm", *s.oscillation_centre_theory * 1e3)
                                    : std::string("none"),
        s.tilt != 0.0 ? fmt::format(", the rig tilted {:+.2f} deg", s.tilt * 180.0 / kPi)
                      : std::string()));
  if (s.drift_speed)
    line(fmt::format("  sideways drift         {:+.3f} mm/s over the run's second half (theory {})",
                     *s.drift_speed * 1e3,
                     s.drift_speed_theory
                         ? fmt::format("{:+.3f} mm/s, v_r sin(skew/2)", *s.drift_speed_theory * 1e3)
                         : std::string("none: guide towers hold the plate, or the rollers' "
                                       "surface speeds differ or change")));
  line(fmt::format(
      "  analytic, thin plate   {:.6f} s{}", s.period_thin,
      period ? fmt::format("  (estimator {:+.4f} %)", 100.0 * (*period / s.period_thin - 1.0))
             : std::string()));
  if (s.period_thick) {
    std::string errors;
    if (period)
      errors += fmt::format("  (estimator {:+.4f} %", 100.0 * (*period / *s.period_thick - 1.0));
    if (s.period_trajectory)
      errors += fmt::format("{}trajectory {:+.4f} %)", period ? ", " : "  (",
                            100.0 * (*s.period_trajectory / *s.period_thick - 1.0));
    else if (period)
      errors += ")";
    line(fmt::format("  analytic, thick plate  {:.6f} s{}", *s.period_thick, errors));
  }
  if (s.paper_period) {
    line(fmt::format(
        "  the paper measured     T = {:.{}f} +- {:.{}f} s, mu_k = {:.{}f} +- {:.{}f} ({})",
        s.paper_period->value, s.paper_period->decimals, s.paper_period->uncertainty,
        s.paper_period->uncertainty_decimals, s.paper_mu_k->value, s.paper_mu_k->decimals,
        s.paper_mu_k->uncertainty, s.paper_mu_k->uncertainty_decimals, s.paper_material));
    if (period)
      line(fmt::format("  simulated - measured   {:+.4f} s = {:+.2f} dT",
                       *period - s.paper_period->value,
                       (*period - s.paper_period->value) / s.paper_period->uncertainty));
  }
  if (s.predicted_integrator_bias)
    line(fmt::format(
        "  integrator bias        {:+.2e} predicted at dt = {:.3g} ms, -(omega dt)^2/24",
        *s.predicted_integrator_bias, s.time_step * 1e3));
  if (s.amplitude_start && s.amplitude_end)
    line(fmt::format("  amplitude              {:.3f} mm at start, {:.3f} mm at end{}",
                     *s.amplitude_start * 1e3, *s.amplitude_end * 1e3,
                     s.amplitude_drift_per_period
                         ? fmt::format(" ({:+.2e} per period)", *s.amplitude_drift_per_period)
                         : std::string()));
  else
    line("  amplitude              none measured: the run reached no turning point");
  if (s.drive) {
    const DriveReport& d = *s.drive;
    line(fmt::format(
        "  motor                  {:.1f} rpm, {:.1f} mN m (the plate's friction takes {:.2f} mN m "
        "at the rollers)",
        d.motor_speed * kRpmPerRadPerSecond, d.motor_torque * 1e3, d.load_torque * 1e3));
    line(gearbox_line(d));
  }
  const std::string speeds =
      std::fabs(s.roller_speed_1 - s.roller_speed) > 1e-9 * std::fabs(s.roller_speed)
          ? fmt::format("{:.0f} rpm (roller 0), {:.0f} rpm (roller 1)",
                        s.roller_speed * kRpmPerRadPerSecond,
                        s.roller_speed_1 * kRpmPerRadPerSecond)
          : fmt::format("{:.0f} rpm", s.roller_speed * kRpmPerRadPerSecond);
  line(fmt::format("  rollers                {}, slip margin {:.2f}", speeds, s.slip_margin));
  line(
      fmt::format("  run                    {:.2f} s simulated in {:.3f} s: {:.0f} x real time, "
                  "{:.0f} steps/s",
                  s.duration, s.wall_s, s.real_time_factor, s.steps_per_second));
  return out;
}

void append_trajectory_row(std::string& out, const TrajectoryRow& row) {
  fmt::format_to(std::back_inserter(out), FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{}\n"), row.t,
                 row.plate.x, row.plate.z, row.plate.pitch, row.plate.vx, row.plate.vz,
                 row.plate.pitch_rate, row.rollers[0].normal_force, row.rollers[0].friction_force,
                 row.rollers[1].normal_force, row.rollers[1].friction_force);
}

void append_hall_row(std::string& out, const HallSample& sample) {
  fmt::format_to(std::back_inserter(out), FMT_COMPILE("{},{}\n"), sample.t_us, sample.adc);
}

std::string trajectory_csv(const RunRecording& r) {
  std::string out(kTrajectoryCsvHeader);
  for (const TrajectoryRow& row : r.trajectory) append_trajectory_row(out, row);
  return out;
}

std::string hall_csv(const RunRecording& r) {
  std::string out(kHallCsvHeader);
  for (const HallSample& s : r.hall) append_hall_row(out, s);
  return out;
}

std::string periods_csv(const RunRecording& r) {
  std::string out = "start_s,end_s,period_s,status\n";
  for (const EstimatedPeriod& p : r.periods) {
    const char* status = p.status == fl_estimator::kAccepted          ? "accepted"
                         : p.status == fl_estimator::kRejectedOutlier ? "rejected: outlier"
                                                                      : "rejected: broken pulse";
    fmt::format_to(std::back_inserter(out), "{},{},{},{}\n", p.start, p.end, p.period, status);
  }
  return out;
}

std::string jumps_csv(const RunRecording& r) {
  std::string out = "roller,start_s,end_s,height_m,roller_angle_rad\n";
  for (const PlateJump& j : r.jumps)
    fmt::format_to(std::back_inserter(out), "{},{},{},{},{}\n", j.roller, j.start, j.end, j.height,
                   j.roller_angle);
  return out;
}

RunOptions recording_for(const OutputDesc& output) {
  RunOptions options;
  options.record_trajectory = output.trajectory;
  options.record_hall = output.hall;
  options.record_cycles = output.cycles;
  return options;
}

std::vector<std::pair<std::string, std::string>> run_output_files(const OutputDesc& output,
                                                                  const CompiledRig& rig,
                                                                  const RunSummary& summary,
                                                                  const RunRecording& recording,
                                                                  StepFiles steps) {
  std::vector<std::pair<std::string, std::string>> files;
  if (output.cycles) files.emplace_back("cycles.csv", cycles_csv(rig, recording.cycles));
  // The steps and samples, unless they were streamed to their files (lab/run/run_files.hpp).
  if (steps == StepFiles::kFromRecording) {
    if (output.trajectory) files.emplace_back("trajectory.csv", trajectory_csv(recording));
    if (output.hall && rig.sensor) files.emplace_back("hall.csv", hall_csv(recording));
  }
  if (output.periods && output.hall && rig.sensor)
    files.emplace_back("periods.csv", periods_csv(recording));
  if (output.jumps && !recording.jumps.empty())
    files.emplace_back("jumps.csv", jumps_csv(recording));
  if (output.summary) {
    files.emplace_back("summary.json", summary_json(summary).dump(2) + "\n");
    files.emplace_back("timing.json", timing_json(summary).dump(2) + "\n");
  }
  return files;
}

void write_run_outputs(const std::string& folder, const OutputDesc& output, const CompiledRig& rig,
                       const RunSummary& summary, const RunRecording& recording) {
  for (const auto& [name, text] : run_output_files(output, rig, summary, recording))
    write_file_atomic(folder + "/" + name, text);
}

}  // namespace fl
