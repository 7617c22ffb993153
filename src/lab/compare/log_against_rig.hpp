// A real log against its simulation: the rig's scene refitted (lab/compare) so that its simulated
// Hall signal has the log's period, simulated again over the log's length at that mu_k, and the
// two signals set side by side: aligned on their first pulse, the residual sample by sample, and
// what the two say differently, each from the same estimator run over both:
//  - the periods' scatter (jumps, an uneven roller or a noisy signal scatter a real log's periods
//    far beyond the simulation's),
//  - periods discarded (bent pulses, missing turning points: jumps),
//  - the period's drift over the log (rollers warming, a motor slowing),
//  - the pulses' width and height (the magnet's distance to the sensor, its size, the sensor's
//    gain, and the plate's speed there),
//  - the baseline's drift (the sensor warming).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hall_log/hall_log.hpp"
#include "lab/compare/compare.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

// What the estimator found in one signal, for the comparison.
struct TraceFacts {
  double duration = 0.0;  // s
  int pulses = 0;
  int periods_used = 0;
  int periods_discarded = 0;
  double period = 0.0;      // s
  double period_std = 0.0;  // s
  // The accepted periods' straight-line trend against time [s per s] and its standard error;
  // null with fewer than three periods.
  std::optional<double> period_drift;
  std::optional<double> period_drift_err;
  std::optional<double> period_scatter_about_trend;  // s, the periods' sd about that line
  double pulse_width = 0.0;                          // s, median time above the timing level
  double pulse_height = 0.0;                         // counts, median peak above the baseline
  double baseline_first = 0.0;                       // counts, before the first pulse
  double baseline_last = 0.0;                        // counts, at the end
};

struct LogAgainstRig {
  std::string log;
  // Asked to stop (CompareOptions::control) before it was done: nothing below is measured.
  bool interrupted = false;
  CompareResult fit;  // the refit (one row)
  double mu_k = 0.0;  // the mu_k the second simulation used: the refit's, else the row's
  TraceFacts measured;
  TraceFacts simulated;
  double shift = 0.0;  // s: a simulated time plus shift is the log's time (first pulses aligned)
  // The residual, measured minus simulated ADC at the log's samples where both exist [counts].
  double residual_rms = 0.0;
  double residual_rms_first_periods = 0.0;  // over the first three periods after alignment
  double residual_rms_last_periods = 0.0;   // over the last three
  std::vector<std::string> disagreements;   // what the two say differently, in words
  // The traces, for the plot: the log's time axis, both signals (the simulated one interpolated,
  // NaN outside the simulated run).
  std::vector<double> t;
  std::vector<double> adc_measured;
  std::vector<double> adc_simulated;
};

// `geometry`: the log's pulses per period (auto: recognised, as estimate does). The spacing and
// gravity the estimator is given set only its mu_k, which the comparison does not use. Throws
// InputError when the log gives no period (as estimate does), or the scene or its refit cannot be
// run.
LogAgainstRig compare_log_with_rig(const HallLog& log, fl_estimator::Geometry geometry,
                                   const CompareOptions& options);

nlohmann::json log_against_rig_json(const LogAgainstRig& r);
// The plot's data (tools/plot_log_vs_sim.py): the report and the traces, long logs thinned.
nlohmann::json log_against_rig_plot_data(const LogAgainstRig& r);

}  // namespace fl
