#include "lab/compare/log_against_rig.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/format.h>

#include "core/oscillation_tracker.hpp"
#include "core/sample_summary.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_table.hpp"
#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

// The median, NaN without samples (a signal whose pulses were all bent).
double median_or_nan(std::vector<double> v) {
  return v.empty() ? std::numeric_limits<double>::quiet_NaN() : median_of(std::move(v));
}

TraceFacts facts_of(const LogEstimate& est) {
  TraceFacts f;
  const fl_estimator::Stats& s = est.stats;
  f.duration = est.duration;
  f.pulses = static_cast<int>(est.pulses.size());
  f.periods_used = static_cast<int>(s.periods_used);
  f.periods_discarded = static_cast<int>(s.periods_discarded);
  f.period = static_cast<double>(s.period_s);
  f.period_std = static_cast<double>(s.period_std_s);
  std::vector<double> widths, heights;
  for (const EstimatedPulse& p : est.pulses) {
    if (p.distorted) continue;
    widths.push_back(p.fall - p.rise);
    heights.push_back(p.peak);
  }
  f.pulse_width = median_or_nan(widths);
  f.pulse_height = median_or_nan(heights);
  f.baseline_first =
      est.pulse_baseline.empty() ? est.baseline : static_cast<double>(est.pulse_baseline.front());
  f.baseline_last = est.baseline;
  // The accepted periods against their middle's time: slope and its standard error.
  std::vector<double> t, p;
  for (const EstimatedPeriod& e : est.periods)
    if (e.status == fl_estimator::kAccepted) {
      t.push_back(0.5 * (e.start + e.end));
      p.push_back(e.period);
    }
  if (t.size() >= 3 && t.front() < t.back()) {
    const LinearFit line = fit_line(t, p);
    f.period_drift = line.slope;
    f.period_drift_err = line.slope_std_error;
    f.period_scatter_about_trend = line.residual_sd;
  }
  return f;
}

// The simulated signal at time `t` on its own axis, linear between samples; NaN outside it.
double interpolate(const HallLog& sim, double t) {
  if (sim.t_s.empty() || t < sim.t_s.front() || t > sim.t_s.back())
    return std::numeric_limits<double>::quiet_NaN();
  const auto hi = std::lower_bound(sim.t_s.begin(), sim.t_s.end(), t);
  if (hi == sim.t_s.begin()) return sim.adc.front();
  const std::size_t j = static_cast<std::size_t>(hi - sim.t_s.begin());
  const double t0 = sim.t_s[j - 1], t1 = sim.t_s[j];
  const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
  return (1.0 - w) * sim.adc[j - 1] + w * sim.adc[j];
}

double rms_between(const LogAgainstRig& r, double from, double to) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    if (r.t[i] < from || r.t[i] > to || std::isnan(r.adc_simulated[i])) continue;
    const double d = r.adc_measured[i] - r.adc_simulated[i];
    sum += d * d;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
}

void find_disagreements(LogAgainstRig& r) {
  const TraceFacts& m = r.measured;
  const TraceFacts& s = r.simulated;
  auto& out = r.disagreements;
  bool drifts = false;
  if (m.period_drift && m.period_drift_err && *m.period_drift_err > 0) {
    const double ds = s.period_drift.value_or(0.0);
    const double es = s.period_drift_err.value_or(0.0);
    const double diff = *m.period_drift - ds;
    drifts = std::fabs(*m.period_drift) > 3.0 * *m.period_drift_err &&
             std::fabs(diff) > 3.0 * std::hypot(*m.period_drift_err, es);
    if (drifts)
      out.push_back(fmt::format(
          "drift: the log's period changes by {:+.2f} +- {:.2f} ms per minute, the simulation's "
          "by {:+.2f}: rollers warming or cooling (friction.warming), or the motor's speed "
          "changing",
          60e3 * *m.period_drift, 60e3 * *m.period_drift_err, 60e3 * ds));
  }
  // The scatter about each signal's own trend, so that a drift does not count twice.
  const double scatter_m = m.period_scatter_about_trend.value_or(m.period_std) / m.period;
  const double scatter_s = s.period_scatter_about_trend.value_or(s.period_std) / s.period;
  if (scatter_m > 3.0 * scatter_s && scatter_m > 2e-3)
    out.push_back(fmt::format(
        "periods: the log's scatter about its trend {:.2f} % against the simulation's {:.3f} %: "
        "jumps of the plate, an uneven roller (rollers.runout), a loose gear, or the timing of "
        "noisy pulses{}",
        100 * scatter_m, 100 * scatter_s, drifts ? ", or a drift that is no straight line" : ""));
  if (m.periods_discarded > s.periods_discarded)
    out.push_back(fmt::format(
        "jumps: the estimator discarded {} of the log's periods against {} simulated (bent "
        "pulses or missing turning points: the plate jumping or being touched)",
        m.periods_discarded, s.periods_discarded));
  const double width = m.pulse_width / s.pulse_width;
  if (std::isfinite(width) && (width < 0.9 || width > 1.1))
    out.push_back(fmt::format(
        "pulse shape: the log's pulses are {:.0f} % {} ({:.1f} ms against {:.1f} ms at the "
        "timing level): the magnet passes the sensor {} than the scene places them "
        "(sensor.position, magnets[].height), or moves {} there (plate.offset: the amplitude)",
        100 * std::fabs(width - 1.0), width > 1 ? "wider" : "narrower", 1e3 * m.pulse_width,
        1e3 * s.pulse_width, width > 1 ? "closer or wider" : "farther or narrower",
        width > 1 ? "slower" : "faster"));
  const double height = m.pulse_height / s.pulse_height;
  if (std::isfinite(height) && (height < 0.8 || height > 1.25))
    out.push_back(fmt::format(
        "pulse height: {:.0f} counts in the log against {:.0f} simulated: the sensor's gain, the "
        "magnet's strength or its height above the sensor differ from the scene's",
        m.pulse_height, s.pulse_height));
  const double baseline_m = m.baseline_last - m.baseline_first;
  const double baseline_s = s.baseline_last - s.baseline_first;
  if (std::fabs(baseline_m - baseline_s) > std::max(3.0, 0.05 * m.pulse_height))
    out.push_back(fmt::format(
        "baseline: the log's baseline moves {:+.1f} counts over the log ({:+.1f} simulated): "
        "the sensor or its supply warming, or a magnet nearby",
        baseline_m, baseline_s));
  if (std::isfinite(r.residual_rms_first_periods) && std::isfinite(r.residual_rms_last_periods) &&
      r.residual_rms_last_periods > 2.0 * r.residual_rms_first_periods &&
      r.residual_rms_last_periods > 0.1 * m.pulse_height)
    out.push_back(fmt::format(
        "phase: the traces drift apart (residual {:.1f} counts rms over the first three periods, "
        "{:.1f} over the last three): the periods agree on average, not period by period",
        r.residual_rms_first_periods, r.residual_rms_last_periods));
}

nlohmann::json facts_json(const TraceFacts& f) {
  return {{"duration_s", f.duration},
          {"pulses", f.pulses},
          {"periods_used", f.periods_used},
          {"periods_discarded", f.periods_discarded},
          {"period_s", f.period},
          {"period_std_s", f.period_std},
          {"period_drift_s_per_s", json_or_null(f.period_drift)},
          {"period_drift_err_s_per_s", json_or_null(f.period_drift_err)},
          {"period_scatter_about_trend_s", json_or_null(f.period_scatter_about_trend)},
          {"pulse_width_s", json_or_null(f.pulse_width)},
          {"pulse_height_counts", json_or_null(f.pulse_height)},
          {"baseline_first_counts", f.baseline_first},
          {"baseline_last_counts", f.baseline_last}};
}

}  // namespace

LogAgainstRig compare_log_with_rig(const HallLog& log, fl_estimator::Geometry geometry,
                                   const CompareOptions& options) {
  LogAgainstRig r;
  r.log = log.path;
  LogSetUp set_up;
  set_up.geometry = geometry;
  const LogEstimate measured = estimate_log(log, set_up, false);
  require_periods(log, measured, "");
  require_geometry(log, measured, check_geometry(log, measured), "");
  r.measured = facts_of(measured);

  // The refit: the log as one measured row, T +- its standard error, on the rig's l +- dl (dl the
  // log's sidecar's, else the estimate's default, the paper's 2 mm): every mu_k from a measured
  // period carries dl (docs/cli.md).
  MeasuredRows rows;
  rows.file = log.path;
  MeasuredRow row;
  row.label = std::filesystem::path(log.path).filename().string();
  row.where = {log.path, 0, 0};
  row.period.value = static_cast<double>(measured.stats.period_s);
  row.period.uncertainty = static_cast<double>(measured.stats.period_sem_s);
  row.period.decimals = 6;
  row.period.uncertainty_decimals = 6;
  row.spacing_err = set_up_for_log(log.file, LogSetUp{}, nullptr).spacing_err;
  rows.rows.push_back(row);
  r.fit = run_compare(rows, options);
  const CompareRow& fitted = r.fit.rows.front();
  if (fitted.status == "interrupted") {
    r.interrupted = true;
    return r;
  }
  if (fitted.status != "compared")
    throw InputError({options.scene_file, 0, 0},
                     "the scene gives no period to set beside the log's at its own mu_k (" +
                         fitted.status + ": " + fitted.reason +
                         "); start it nearer the log's mu_k with " +
                         field_ref("set", "friction.mu_k=..."));
  r.mu_k = fitted.mu_k_refit.value_or(fitted.mu_k_simulated);

  // The simulation at that mu_k, over the log's length plus the periods before its first pulse.
  std::vector<SceneOverride> overrides = options.overrides;
  overrides.push_back({"friction.mu_k", fmt::format("{}", r.mu_k)});
  overrides.push_back(
      {"world.duration", fmt::format("{} s", r.measured.duration + 4.0 * r.measured.period)});
  const Scene scene = load_scene_file(options.scene_file, overrides, options.paper, options.parts);
  RunOptions run;
  run.record_hall = true;
  run.stop = options.control.stop;
  RunRecording recording;
  const RunSummary summary = run_experiment(scene, run, &recording);
  if (summary.interrupted_at) {
    r.interrupted = true;
    return r;
  }
  if (summary.failure) throw std::runtime_error("the simulation failed: " + *summary.failure);
  std::vector<double> t_s, adc;
  for (const HallSample& s : recording.hall) {
    t_s.push_back(s.t_us * 1e-6);
    adc.push_back(s.adc);
  }
  const HallLog sim = hall_log_from_samples(std::move(t_s), adc, "the simulation");
  LogSetUp sim_set_up = set_up;
  sim_set_up.spacing = scene.rollers.spacing;
  sim_set_up.geometry = measured.geometry;
  const LogEstimate simulated = estimate_log(sim, sim_set_up, false);
  if (simulated.pulses.empty() || simulated.stats.periods_used == 0)
    throw std::runtime_error(
        "the simulated signal gives no period: does the scene's sensor see "
        "the magnet? (frictionlab run the scene and look at hall.csv)");
  r.simulated = facts_of(simulated);

  // Aligned on the first pulse; the residual at the log's samples.
  r.shift = measured.pulses.front().time - simulated.pulses.front().time;
  r.t = log.t_s;
  r.adc_measured.assign(log.adc.begin(), log.adc.end());
  r.adc_simulated.reserve(log.t_s.size());
  for (double t : log.t_s) r.adc_simulated.push_back(interpolate(sim, t - r.shift));
  const double first = measured.pulses.front().time;
  const double last = log.t_s.back();
  r.residual_rms = rms_between(r, first, last);
  r.residual_rms_first_periods = rms_between(r, first, first + 3.0 * r.measured.period);
  r.residual_rms_last_periods = rms_between(r, last - 3.0 * r.measured.period, last);
  find_disagreements(r);
  return r;
}

nlohmann::json log_against_rig_json(const LogAgainstRig& r) {
  const CompareRow& row = r.fit.rows.front();
  return {{"log", escape_invalid_utf8(r.log)},
          {"scene", escape_invalid_utf8(r.fit.scene)},
          {"spacing_m", row.spacing},
          {"spacing_err_m", json_or_null(row.spacing_err)},
          {"h_c_m", row.h_c},
          {"period_measured_s", row.period_measured.value},
          {"period_measured_err_s", row.period_measured.uncertainty},
          {"mu_k_scene", row.mu_k_simulated},
          {"period_at_scene_mu_k_s", json_or_null(row.period_simulated)},
          {"mu_k_refit", json_or_null(row.mu_k_refit)},
          {"mu_k_refit_err_quadrature", json_or_null(row.mu_k_refit_err_quadrature)},
          {"refit_note", row.refit_note},
          {"mu_k_simulated", r.mu_k},
          {"shift_s", r.shift},
          {"residual_rms_counts", r.residual_rms},
          {"residual_rms_first_periods_counts", json_or_null(r.residual_rms_first_periods)},
          {"residual_rms_last_periods_counts", json_or_null(r.residual_rms_last_periods)},
          {"measured", facts_json(r.measured)},
          {"simulated", facts_json(r.simulated)},
          {"disagreements", r.disagreements},
          {"simulations", r.fit.simulations + 1}};
}

nlohmann::json log_against_rig_plot_data(const LogAgainstRig& r) {
  nlohmann::json data = log_against_rig_json(r);
  // At most about 20000 points: every k-th sample (the plot shows pulses tens of samples wide).
  const std::size_t step = std::max<std::size_t>(1, r.t.size() / 20000);
  nlohmann::json t = nlohmann::json::array(), m = nlohmann::json::array(),
                 s = nlohmann::json::array();
  for (std::size_t i = 0; i < r.t.size(); i += step) {
    t.push_back(r.t[i]);
    m.push_back(r.adc_measured[i]);
    s.push_back(json_or_null(r.adc_simulated[i]));
  }
  data["t_s"] = std::move(t);
  data["adc_measured"] = std::move(m);
  data["adc_simulated"] = std::move(s);
  return data;
}

}  // namespace fl
