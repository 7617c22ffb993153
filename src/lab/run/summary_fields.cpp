#include "lab/run/summary_fields.hpp"

#include <cmath>

#include "io/json_value.hpp"

namespace fl {
namespace {

using json = nlohmann::json;

std::optional<double> relative_error(const std::optional<double>& value,
                                     const std::optional<double>& reference) {
  if (!value || !reference) return std::nullopt;
  return *value / *reference - 1.0;
}

// Where mu_k came from when not from the rig's estimator (none when it did).
FieldValue mu_k_source_value(const RunSummary& s) {
  if (!s.mu_k_source || *s.mu_k_source == PeriodSource::kHallEstimator) return {};
  return FieldValue::text(s.estimator ? "trajectory: the rig's estimator accepted no period"
                                      : "trajectory: the scene has no sensor");
}

json estimator_json(const EstimatorReport& e) {
  return json{{"periods_used", e.periods_used},
              {"periods_discarded", e.periods_discarded},
              {"pulses", e.pulses},
              {"period_s", e.period},
              {"period_std_s", e.period_std},
              {"period_std_error_s", e.period_std_error},
              {"mu_k", e.mu_k},
              {"mu_k_err_worst", e.mu_k_err_worst},
              {"mu_k_err_quadrature", e.mu_k_err_quadrature}};
}

FieldValue drive_value(const RunSummary& s) {
  if (!s.drive) return {};
  const DriveReport& d = *s.drive;
  return FieldValue::object(json{{"motor_speed_rad_s", d.motor_speed},
                                 {"motor_torque_n_m", d.motor_torque},
                                 {"roller_speeds_rad_s", {d.roller_speeds[0], d.roller_speeds[1]}},
                                 {"gearbox_ratio", d.gearbox_ratio},
                                 {"turning_fraction", d.turning_fraction},
                                 {"speed_ratio", json_or_null(d.speed_ratio)},
                                 {"speed_ratio_error", json_or_null(d.speed_ratio_error)},
                                 {"senses_opposite", json_or_null(d.senses_opposite)},
                                 {"load_torque_n_m", d.load_torque}});
}

FieldValue paper_value(const RunSummary& s) {
  if (!s.paper_period || !s.paper_mu_k) return {};
  return FieldValue::object(json{{"material", s.paper_material},
                                 {"period_s", s.paper_period->value},
                                 {"period_err_s", s.paper_period->uncertainty},
                                 {"mu_k", s.paper_mu_k->value},
                                 {"mu_k_err", s.paper_mu_k->uncertainty}});
}

json warming_window_json(const std::optional<WarmingWindow>& w) {
  if (!w) return nullptr;
  return json{{"periods", w->periods}, {"period_s", w->period}, {"mu_k", w->mu_k}};
}

FieldValue warming_value(const RunSummary& s) {
  if (!s.warming) return {};
  const WarmingReport& w = *s.warming;
  return FieldValue::object(json{{"start_temperature_k", w.start_temperature},
                                 {"room_temperature_k", w.room_temperature},
                                 {"time_constant_s", w.time_constant},
                                 {"hold_s", w.hold},
                                 {"mu_k_start", w.mu_k_start},
                                 {"mu_k_room", w.mu_k_room},
                                 {"end_temperature_k", w.end_temperature},
                                 {"mu_k_end", w.mu_k_end},
                                 {"mu_k_cold_paper_formula", w.mu_k_cold_paper_formula},
                                 {"first_10_periods", warming_window_json(w.first_10_periods)},
                                 {"first_30_s", warming_window_json(w.first_30_s)},
                                 {"whole_run", warming_window_json(w.whole_run)}});
}

using S = const RunSummary&;
using V = FieldValue;
using T = FieldType;
constexpr const char* kNoPeriod = "there is no headline period (period_withheld says why)";
constexpr const char* kNoEstimatorSpread =
    "the scene has no sensor, or its estimator accepted fewer than two periods";
constexpr const char* kNoRestoring = "the plate has no restoring force (l <= 2 mu_k h_c)";

// The run, its regime and the conditioning of mu_k on what was measured.
std::vector<SummaryField> run_fields() {
  // clang-format off
  return {
      {.json = "scene", .python = "scene", .type = T::kText,
       .meaning = "the scene's name (its `name:`, else its file's)",
       .get = [](S s) { return V::text(s.scene); }},
      {.json = "seed", .sweep = "seed", .python = "seed", .type = T::kInteger,
       .meaning = "`world.seed`, which draws the sensor's noise and jitter: `frictionlab run` with "
                  "a sweep point's overrides (its `set` in sweep.json) and this seed replays it",
       .get = [](S s) { return V::whole(s.seed); }},
      {.sweep = "status", .type = T::kText,
       .meaning = "`ok`; `failed` when a guard stopped the run, its regime is `numerically "
                  "failed` or it threw (a run of it alone exits 3); `invalid` when the scene "
                  "refused the point's overrides",
       .get = [](S s) { return V::text(s.failed() ? "failed" : "ok"); }},
      {.json = "regime", .sweep = "regime", .python = "regime", .python_type = "Regime",
       .type = T::kText,
       .meaning = "what the trajectory shows: `oscillates`, `clipped`, `stick-slip`, `grows`, "
                  "`decays`, `sticks`, `tips`, `no restoring force`, `lost` or `numerically failed` "
                  "(docs/physics.md)",
       .get = [](S s) { return V::text(regime_name(s.regime)); }},
      {.json = "regime_since_s", .python = "regime_since", .unit = "s",
       .meaning = "when the regime began",
       .get = [](S s) { return V::number(s.regime_since); }},
      {.json = "period_withheld", .python = "period_withheld", .type = T::kText,
       .meaning = "why there is no headline period (any regime but `oscillates`, `clipped`, "
                  "`grows`, `decays`)",
       .null_when = "there is a headline period",
       .get = [](S s) { return V::text(s.period_withheld); }},
      {.json = "failure", .python = "failure", .type = T::kText,
       .meaning = "the guard's message when one stopped the run",
       .null_when = "no guard stopped the run",
       .get = [](S s) { return V::text(s.failure); }},
      {.json = "interrupted_at_s", .python = "interrupted_at", .unit = "s",
       .meaning = "where Ctrl-C or SIGTERM ended the run before its duration",
       .null_when = "the run was not interrupted (left out of summary.json)",
       .get = [](S s) { return V::number(s.interrupted_at); }, .omit_when_null = true},
      {.json = "estimator_disagreement", .python = "estimator_disagreement", .type = T::kText,
       .meaning = "set when the estimator's period and the trajectory's differ beyond their "
                  "uncertainties",
       .null_when = "they agree, or one of them is missing",
       .get = [](S s) { return V::text(s.estimator_disagreement); }},
      {.json = "condition_period", .python = "condition_period",
       .meaning = "d ln mu_k / d ln T through the thick formula",
       .get = [](S s) { return V::number(s.condition_period); }},
      {.json = "condition_spacing", .python = "condition_spacing",
       .meaning = "d ln mu_k / d ln l through the thick formula",
       .get = [](S s) { return V::number(s.condition_spacing); }},
      {.json = "condition_h_c", .python = "condition_h_c",
       .meaning = "d ln mu_k / d ln h_c through the thick formula",
       .get = [](S s) { return V::number(s.condition_h_c); }},
  };
  // clang-format on
}

// The periods: the estimator's, the trajectory's, the closed forms', and where the plate
// oscillates.
std::vector<SummaryField> period_fields() {
  // clang-format off
  return {
      {.json = "period_s", .sweep = "period_s", .python = "period", .unit = "s",
       .meaning = "the headline period: the rig's estimator's mean T from the simulated Hall "
                  "signal, for a harmonic oscillation only",
       .null_when = "the regime is not harmonic, or the estimator accepted no period",
       .get = [](S s) { return V::number(s.period); }},
      {.json = "period_std_s", .sweep = "period_std_s", .unit = "s",
       .meaning = "dT: the standard deviation of the estimator's periods (the paper's convention)",
       .null_when = kNoEstimatorSpread,
       .get = [](S s) {
         return s.estimator && s.estimator->has_spread() ? V::number(s.estimator->period_std)
                                                              : V();
       }},
      {.json = "period_std_error_s", .sweep = "period_std_error_s", .unit = "s",
       .meaning = "the standard error of the estimator's mean period",
       .null_when = kNoEstimatorSpread,
       .get = [](S s) {
         return s.estimator && s.estimator->has_spread()
                    ? V::number(s.estimator->period_std_error)
                    : V();
       }},
      {.json = "periods_used", .sweep = "periods_used", .type = T::kInteger,
       .meaning = "N: the periods the rig's estimator accepted",
       .null_when = "the scene has no sensor",
       .get = [](S s) {
         return s.estimator ? V::whole(std::int64_t{s.estimator->periods_used}) : V();
       }},
      {.json = "periods_discarded", .sweep = "periods_discarded", .type = T::kInteger,
       .meaning = "the periods the rig's estimator rejected (an outlier, a broken pulse)",
       .null_when = "the scene has no sensor",
       .get = [](S s) {
         return s.estimator ? V::whole(std::int64_t{s.estimator->periods_discarded}) : V();
       }},
      {.json = "period_trajectory_s", .sweep = "period_trajectory_s", .python = "period_trajectory",
       .unit = "s",
       .meaning = "the trajectory's own period, from the crossings of the oscillation's centre",
       .null_when = "the regime is not harmonic",
       .get = [](S s) { return V::number(s.period_trajectory); }},
      {.json = "period_trajectory_err_s", .python = "period_trajectory_err", .unit = "s",
       .meaning = "the standard error of the trajectory's period",
       .null_when = "the regime is not harmonic",
       .get = [](S s) { return V::number(s.period_trajectory_err); }},
      {.json = "oscillation_centre_m", .sweep = "oscillation_centre_m",
       .python = "oscillation_centre", .unit = "m",
       .meaning = "the oscillation's centre: the mean of the midpoints of successive turning "
                  "points over the cycles the period is read from",
       .null_when = "there is no trajectory period",
       .get = [](S s) { return V::number(s.oscillation_centre); }},
      {.json = "oscillation_centre_theory_m", .sweep = "oscillation_centre_theory_m",
       .python = "oscillation_centre_theory", .unit = "m",
       .meaning = "the closed form's centre: a tilted rig's x_eq, 0 on a level rig",
       .null_when = kNoRestoring,
       .get = [](S s) { return V::number(s.oscillation_centre_theory); }},
      {.json = "drift_speed_m_s", .sweep = "drift_speed_m_s", .python = "drift_speed",
       .unit = "m/s",
       .meaning = "skewed axes (`rollers.skew`): the plate's sideways drift along +y over the "
                  "run's second half",
       .null_when = "the rollers are not skewed",
       .get = [](S s) { return V::number(s.drift_speed); }},
      {.json = "drift_speed_theory_m_s", .sweep = "drift_speed_theory_m_s",
       .python = "drift_speed_theory", .unit = "m/s",
       .meaning = "theory's sideways drift, v_r sin(skew / 2)",
       .null_when = "the rollers are not skewed, or their speeds differ or change",
       .get = [](S s) { return V::number(s.drift_speed_theory); }},
      {.json = "tilt_rad", .python = "tilt", .unit = "rad", .meaning = "`world.tilt`",
       .get = [](S s) { return V::number(s.tilt); }},
      {.json = "period_thin_s", .sweep = "period_thin_s", .python = "period_thin", .unit = "s",
       .meaning = "the paper's period pi sqrt(2 l / (mu_k g)) for the scene's mu_k",
       .get = [](S s) { return V::number(s.period_thin); }},
      {.json = "period_thick_s", .sweep = "period_thick_s", .python = "period_thick", .unit = "s",
       .meaning = "the thick plate's period pi sqrt(2 (l - 2 mu_k h_c) / (mu_k g))",
       .null_when = kNoRestoring,
       .get = [](S s) { return V::number(s.period_thick); }},
      {.json = "error_vs_thin", .sweep = "error_vs_thin",
       .meaning = "the headline period against the thin formula's: T / T_thin - 1",
       .null_when = kNoPeriod,
       .get = [](S s) { return V::number(relative_error(s.period, s.period_thin)); }},
      {.json = "error_vs_thick", .sweep = "error_vs_thick",
       .meaning = "the headline period against the thick formula's: T / T_thick - 1",
       .null_when = kNoPeriod,
       .get = [](S s) { return V::number(relative_error(s.period, s.period_thick)); }},
      {.json = "trajectory_error_vs_thick",
       .meaning = "the trajectory's period against the thick formula's",
       .null_when = "there is no trajectory period",
       .get = [](S s) {
         return V::number(relative_error(s.period_trajectory, s.period_thick));
       }},
  };
  // clang-format on
}

// mu_k: set, recovered, and the sensor's own errors.
std::vector<SummaryField> mu_k_fields() {
  // clang-format off
  return {
      {.json = "mu_k_set", .sweep = "mu_k_set", .python = "mu_k_set",
       .meaning = "the scene's mu_k (at the start, for rollers that warm)",
       .get = [](S s) { return V::number(s.mu_k_set); }},
      {.json = "mu_k_recovered", .sweep = "mu_k_recovered", .python = "mu_k_recovered",
       .meaning = "mu_k from the headline period through the paper's (thin) formula; from the "
                  "trajectory's period when `mu_k_source` says so",
       .null_when = "the regime is not harmonic",
       .get = [](S s) { return V::number(s.mu_k_recovered); }},
      {.json = "mu_k_source", .sweep = "mu_k_source", .type = T::kText,
       .meaning = "where mu_k came from when not from the rig's estimator: `trajectory: the "
                  "scene has no sensor` or `trajectory: the rig's estimator accepted no period`",
       .null_when = "mu_k came from the rig's estimator (left out of summary.json)",
       .get = mu_k_source_value, .omit_when_null = true},
      {.python = "mu_k_source", .python_type = "PeriodSource", .type = T::kText,
       .meaning = "where mu_k came from: the rig's estimator or the trajectory",
       .null_when = "the regime is not harmonic",
       .get = [](S s) {
         if (!s.mu_k_source) return V();
         return V::text(*s.mu_k_source == PeriodSource::kHallEstimator ? "hall estimator"
                                                                       : "trajectory");
       }},
      {.json = "mu_k_recovered_thick", .sweep = "mu_k_recovered_thick",
       .python = "mu_k_recovered_thick",
       .meaning = "mu_k from the same period through the thick formula with the rig's h_c",
       .null_when = "the regime is not harmonic",
       .get = [](S s) { return V::number(s.mu_k_recovered_thick); }},
      {.json = "mu_k_estimator", .python = "mu_k_estimator",
       .meaning = "the estimator's own mu_k (thin formula)",
       .null_when = "the estimator accepted no period (left out of summary.json)",
       .get = [](S s) { return V::number(s.mu_k_estimator); }, .omit_when_null = true},
      {.json = "mu_k_err_worst", .sweep = "mu_k_err_worst", .python = "mu_k_err_worst",
       .meaning = "d mu_k, the paper's worst case: mu_k (dl / l + 2 dT / T), dl = 2 mm",
       .null_when = "fewer than two accepted periods (left out of summary.json)",
       .get = [](S s) { return V::number(s.mu_k_err_worst); }, .omit_when_null = true},
      {.json = "mu_k_err_quadrature", .sweep = "mu_k_err_quadrature",
       .python = "mu_k_err_quadrature",
       .meaning = "d mu_k in quadrature: mu_k sqrt((dl / l)^2 + (2 dT / T)^2)",
       .null_when = "fewer than two accepted periods (left out of summary.json)",
       .get = [](S s) { return V::number(s.mu_k_err_quadrature); }, .omit_when_null = true},
      {.python = "estimator", .python_type = "EstimatorReport", .type = T::kObject,
       .meaning = "the rig's estimator's report: periods_used, periods_discarded, pulses, period, "
                  "period_std, period_std_error, mu_k, mu_k_err_worst, mu_k_err_quadrature",
       .null_when = "the scene has no sensor",
       .get = [](S s) { return s.estimator ? V::object(estimator_json(*s.estimator)) : V(); }},
      {.json = "predicted_integrator_bias", .python = "predicted_integrator_bias",
       .meaning = "the semi-implicit Euler step's period error, -(omega dt)^2 / 24",
       .null_when = kNoRestoring,
       .get = [](S s) { return V::number(s.predicted_integrator_bias); }},
      {.json = "sensor_clock_error", .python = "clock_error",
       .meaning = "the sensor board's clock runs fast by this fraction (`sensor.clock_error`)",
       .null_when = "the clock is exact (left out of summary.json)",
       .get = [](S s) { return V::number(s.clock_error); }, .omit_when_null = true},
      {.json = "clock_mu_k_bias",
       .meaning = "what the clock's error does to mu_k: 1 / (1 + e)^2 - 1",
       .null_when = "the clock is exact (left out of summary.json)",
       .get = [](S s) {
         return s.clock_error
                    ? V::number(1.0 / ((1.0 + *s.clock_error) * (1.0 + *s.clock_error)) - 1.0)
                    : V();
       },
       .omit_when_null = true},
  };
  // clang-format on
}

// The rig: its rollers, plate and drive.
std::vector<SummaryField> rig_fields() {
  // clang-format off
  return {
      {.json = "runout_m", .sweep = "runout_m", .python = "runout", .unit = "m",
       .meaning = "the rollers' run-out (`rollers.runout`)",
       .null_when = "the rollers are true (left out of summary.json)",
       .get = [](S s) { return V::number(s.runout); }, .omit_when_null = true},
      {.json = "runout_threshold_m", .sweep = "runout_threshold_m", .python = "runout_threshold",
       .unit = "m",
       .meaning = "theory's run-out above which the plate hops, at the start amplitude's turning "
                  "points and the rollers' mean speed (docs/physics.md)",
       .null_when = "the rollers are true (left out of summary.json)",
       .get = [](S s) { return V::number(s.runout_threshold); }, .omit_when_null = true},
      {.json = "spacing_m", .sweep = "spacing_m", .python = "spacing", .unit = "m",
       .meaning = "l, the rollers' spacing",
       .get = [](S s) { return V::number(s.spacing); }},
      {.json = "h_c_m", .sweep = "h_c_m", .python = "h_c", .unit = "m",
       .meaning = "the plate's centre of mass above the contact line",
       .get = [](S s) { return V::number(s.h_c); }},
      {.json = "plate_mass_kg", .python = "plate_mass", .unit = "kg",
       .meaning = "the plate with what it carries",
       .get = [](S s) { return V::number(s.plate_mass); }},
      {.sweep = "temperature_k", .python = "temperature", .unit = "K",
       .meaning = "the rollers' temperature at the start (`friction.temperature`)",
       .get = [](S s) { return V::number(s.temperature); }},
      {.sweep = "gravity_m_s2", .python = "gravity", .unit = "m/s^2", .meaning = "g",
       .get = [](S s) { return V::number(s.gravity); }},
      {.json = "roller_speed_rad_s", .sweep = "roller_speed_rad_s", .python = "roller_speed",
       .unit = "rad/s",
       .meaning = "roller 0's speed (at -l/2; the mean over the run when ramped or driven)",
       .get = [](S s) { return V::number(s.roller_speed); }},
      {.json = "roller_speed_1_rad_s", .sweep = "roller_speed_1_rad_s",
       .python = "roller_speed_1", .unit = "rad/s",
       .meaning = "roller 1's speed (at +l/2; the mean over the run when ramped or driven)",
       .get = [](S s) { return V::number(s.roller_speed_1); }},
      {.json = "drive", .python = "drive", .python_type = "DriveReport", .type = T::kObject,
       .meaning = "the motor and gears: `motor_speed_rad_s`, `motor_torque_n_m`, "
                  "`roller_speeds_rad_s`, `gearbox_ratio`, `turning_fraction` (the share of steps "
                  "in which the motor and both rollers turned), `speed_ratio`, "
                  "`speed_ratio_error`, `senses_opposite` (these three over the turning steps; "
                  "null when the train never turned), `load_torque_n_m`",
       .null_when = "the drive is ideal (no motor)",
       .get = drive_value},
      {.json = "plate_speed_max_m_s", .python = "plate_speed_max", .unit = "m/s",
       .meaning = "the plate's largest speed over the run",
       .get = [](S s) { return V::number(s.plate_speed_max); }},
      {.json = "slip_margin", .sweep = "slip_margin", .python = "slip_margin",
       .meaning = "the rollers' surface speed over the plate's largest speed: infinite (JSON: "
                  "null) when the plate never moved",
       .get = [](S s) { return V::number(s.slip_margin); }},
      {.sweep = "slip_threshold_rad_s", .python = "slip_threshold", .unit = "rad/s",
       .meaning = "the rollers' speed at which their surface keeps up with the plate's largest "
                  "speed, A omega, for the scene's initial amplitude",
       .null_when = kNoRestoring,
       .get = [](S s) { return V::number(s.slip_threshold); }},
  };
  // clang-format on
}

// The motion: amplitude, clipping, stick-slip, growth and jumps.
std::vector<SummaryField> motion_fields() {
  // clang-format off
  return {
      {.json = "amplitude_start_m", .sweep = "amplitude_start_m", .python = "amplitude_start",
       .unit = "m", .meaning = "the first turning point's distance from the centre",
       .null_when = "the run reached no turning point",
       .get = [](S s) { return V::number(s.amplitude_start); }},
      {.json = "amplitude_end_m", .sweep = "amplitude_end_m", .python = "amplitude_end",
       .unit = "m", .meaning = "the last turning point's distance from the centre",
       .null_when = "the run reached no turning point",
       .get = [](S s) { return V::number(s.amplitude_end); }},
      {.json = "amplitude_drift_per_period", .python = "amplitude_drift_per_period",
       .meaning = "the amplitude's relative change per period",
       .null_when = "the run reached fewer than two turning points",
       .get = [](S s) { return V::number(s.amplitude_drift_per_period); }},
      {.json = "clip_time_s", .sweep = "clip_time_s", .python = "clip_time", .unit = "s",
       .meaning = "`clipped`: when the first stick began",
       .null_when = "the regime is not `clipped` (left out of summary.json)",
       .get = [](S s) { return V::number(s.clip_time); }, .omit_when_null = true},
      {.json = "amplitude_before_clip_m", .python = "amplitude_before_clip", .unit = "m",
       .meaning = "`clipped`: the amplitude before the first stick",
       .null_when = "the regime is not `clipped` (left out of summary.json)",
       .get = [](S s) { return V::number(s.amplitude_before_clip); }, .omit_when_null = true},
      {.json = "amplitude_clipped_m", .sweep = "amplitude_clipped_m",
       .python = "amplitude_clipped", .unit = "m",
       .meaning = "`clipped`: the settled amplitude after the sticks",
       .null_when = "the regime is not `clipped` (left out of summary.json)",
       .get = [](S s) { return V::number(s.amplitude_clipped); }, .omit_when_null = true},
      {.json = "stick_slip_period_s", .sweep = "stick_slip_period_s",
       .python = "stick_slip_period", .unit = "s", .meaning = "`stick-slip`: the cycle's period",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_slip_period); }, .omit_when_null = true},
      {.json = "stick_slip_amplitude_m", .sweep = "stick_slip_amplitude_m",
       .python = "stick_slip_amplitude", .unit = "m",
       .meaning = "`stick-slip`: the cycle's amplitude",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_slip_amplitude); }, .omit_when_null = true},
      {.json = "stick_duration_s", .python = "stick_duration", .unit = "s",
       .meaning = "`stick-slip`: one stick phase",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_duration); }, .omit_when_null = true},
      {.json = "growth_rate_per_s", .sweep = "growth_rate_per_s", .python = "growth_rate",
       .unit = "1/s",
       .meaning = "`grows`, `decays`: d ln A / dt measured at the turning points",
       .null_when = "the regime is neither (left out of summary.json)",
       .get = [](S s) { return V::number(s.growth_rate); }, .omit_when_null = true},
      {.json = "e_folding_time_s", .python = "e_folding_time", .unit = "s",
       .meaning = "`grows`, `decays`: 1 / |growth rate|",
       .null_when = "the regime is neither (left out of summary.json)",
       .get = [](S s) { return V::number(s.e_folding_time); }, .omit_when_null = true},
      {.json = "jumps", .sweep = "jumps", .python = "jumps", .type = T::kInteger,
       .meaning = "how many times the plate left a roller (a tube off its shaft)",
       .null_when = "the plate never left (left out of summary.json)",
       .get = [](S s) { return V::whole(s.jumps); }, .omit_when_null = true},
      {.json = "first_jump_time_s", .python = "first_jump_time", .unit = "s",
       .meaning = "when the plate first left a roller",
       .null_when = "the plate never left (left out of summary.json)",
       .get = [](S s) { return V::number(s.first_jump_time); }, .omit_when_null = true},
      {.json = "longest_jump_s", .python = "longest_jump", .unit = "s",
       .meaning = "the longest time off a roller",
       .null_when = "the plate never left (left out of summary.json)",
       .get = [](S s) { return V::number(s.longest_jump); }, .omit_when_null = true},
      {.json = "highest_jump_m", .sweep = "highest_jump_m", .python = "highest_jump", .unit = "m",
       .meaning = "the largest gap between the plate's bottom and a roller",
       .null_when = "the plate never left (left out of summary.json)",
       .get = [](S s) { return V::number(s.highest_jump); }, .omit_when_null = true},
  };
  // clang-format on
}

// What theory has for the regime, the rollers warming, and the paper's values.
std::vector<SummaryField> theory_fields() {
  // clang-format off
  return {
      {.json = "regime_theory", .python = "regime_theory", .python_type = "Regime",
       .type = T::kText,
       .meaning = "the regime the friction law's closed forms give for the scene "
                  "(docs/friction-laws.md)",
       .null_when = "the regime is not `clipped`, `stick-slip`, `grows` or `decays` (left out of "
                    "summary.json)",
       .get = [](S s) {
         return s.regime_theory ? V::text(regime_name(*s.regime_theory)) : V();
       },
       .omit_when_null = true},
      {.json = "amplitude_clipped_theory_m", .python = "amplitude_clipped_theory", .unit = "m",
       .meaning = "theory's clipped amplitude, v_r / Omega",
       .null_when = "the regime is not `clipped` (left out of summary.json)",
       .get = [](S s) { return V::number(s.amplitude_clipped_theory); }, .omit_when_null = true},
      {.json = "stick_slip_period_theory_s", .python = "stick_slip_period_theory", .unit = "s",
       .meaning = "the stick-slip cycle's period, closed form",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_slip_period_theory); }, .omit_when_null = true},
      {.json = "stick_slip_amplitude_theory_m", .python = "stick_slip_amplitude_theory",
       .unit = "m", .meaning = "the stick-slip cycle's amplitude, closed form",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_slip_amplitude_theory); },
       .omit_when_null = true},
      {.json = "stick_duration_theory_s", .python = "stick_duration_theory", .unit = "s",
       .meaning = "one stick phase, closed form",
       .null_when = "the regime is not `stick-slip` (left out of summary.json)",
       .get = [](S s) { return V::number(s.stick_duration_theory); }, .omit_when_null = true},
      {.json = "growth_rate_theory_per_s", .python = "growth_rate_theory", .unit = "1/s",
       .meaning = "theory's growth rate, averaged over the start's cycle",
       .null_when = "the regime is neither `grows` nor `decays` (left out of summary.json)",
       .get = [](S s) { return V::number(s.growth_rate_theory); }, .omit_when_null = true},
      {.json = "warming", .python = "warming", .python_type = "WarmingReport", .type = T::kObject,
       .meaning = "rollers warming (`friction.warming`): `start_temperature_k`, "
                  "`room_temperature_k`, `time_constant_s`, `hold_s`, `mu_k_start`, `mu_k_room`, "
                  "`end_temperature_k`, `mu_k_end`, `mu_k_cold_paper_formula` (the paper's "
                  "formula on rollers that stay cold), and the windows `first_10_periods`, "
                  "`first_30_s`, `whole_run`, each `{periods, period_s, mu_k}` from the "
                  "estimator's accepted periods (null when a window holds none)",
       .null_when = "the rollers do not warm (left out of summary.json)",
       .get = warming_value, .omit_when_null = true},
      {.json = "paper", .type = T::kObject,
       .meaning = "what the paper measured for the scene's material: `material`, `period_s`, "
                  "`period_err_s`, `mu_k`, `mu_k_err`",
       .null_when = "the scene's mu_k is not a row of the paper's Table I (left out of "
                    "summary.json)",
       .get = paper_value, .omit_when_null = true},
      {.sweep = "paper_material", .python = "paper_material", .type = T::kText,
       .meaning = "the Table I key the scene took mu_k from",
       .null_when = "the scene's mu_k is not a row of the paper's Table I",
       .get = [](S s) { return s.paper_period ? V::text(s.paper_material) : V(); }},
      {.sweep = "paper_period_s", .python = "paper_period", .python_type = "Measured",
       .unit = "s", .meaning = "the period the paper measured (Python: T +- dT)",
       .null_when = "the scene's mu_k is not a row of the paper's Table I",
       .get = [](S s) { return s.paper_period ? V::number(s.paper_period->value) : V(); }},
      {.sweep = "paper_period_err_s", .unit = "s", .meaning = "its dT",
       .null_when = "the scene's mu_k is not a row of the paper's Table I",
       .get = [](S s) { return s.paper_period ? V::number(s.paper_period->uncertainty) : V(); }},
      {.sweep = "paper_mu_k", .python = "paper_mu_k", .python_type = "Measured",
       .meaning = "the mu_k the paper printed (Python: mu_k +- d mu_k)",
       .null_when = "the scene's mu_k is not a row of the paper's Table I",
       .get = [](S s) { return s.paper_mu_k ? V::number(s.paper_mu_k->value) : V(); }},
      {.sweep = "paper_mu_k_err", .meaning = "its d mu_k",
       .null_when = "the scene's mu_k is not a row of the paper's Table I",
       .get = [](S s) { return s.paper_mu_k ? V::number(s.paper_mu_k->uncertainty) : V(); }},
  };
  // clang-format on
}

// The numerics and what the run cost.
std::vector<SummaryField> numerics_fields() {
  // clang-format off
  return {
      {.json = "min_normal_force_n", .python = "min_normal_force", .unit = "N",
       .meaning = "the smallest normal force on the plate at a roller over the run",
       .get = [](S s) { return V::number(s.min_normal_force); }},
      {.json = "max_penetration_m", .python = "max_penetration", .unit = "m",
       .meaning = "the plate's deepest penetration into a roller over the run",
       .get = [](S s) { return V::number(s.max_penetration); }},
      {.json = "time_step_s", .sweep = "time_step_s", .python = "time_step", .unit = "s",
       .meaning = "the physics step (`world.time_step`, or the one an accuracy chose)",
       .get = [](S s) { return V::number(s.time_step); }},
      {.json = "solver_iterations", .python = "solver_iterations", .type = T::kInteger,
       .meaning = "the contact solver's iterations the run ended with",
       .get = [](S s) { return V::whole(std::int64_t{s.solver_iterations}); }},
      {.json = "solver_iterations_raised", .python = "solver_iterations_raised", .type = T::kText,
       .meaning = "from which iterations to which the run raised them, and why",
       .null_when = "the contact solver converged at the scene's (left out of summary.json)",
       .get = [](S s) { return V::text(s.solver_iterations_raised); }, .omit_when_null = true},
      {.json = "duration_s", .sweep = "duration_s", .python = "duration", .unit = "s",
       .meaning = "simulated time", .get = [](S s) { return V::number(s.duration); }},
      {.json = "steps", .sweep = "steps", .python = "steps", .type = T::kInteger,
       .meaning = "physics steps taken",
       .get = [](S s) { return V::whole(std::int64_t{s.steps}); }},
      {.json = "regime_evidence", .sweep = "regime_detail", .python = "regime_evidence",
       .type = T::kText, .meaning = "what showed the regime (which force, which speed)",
       .get = [](S s) { return V::text(s.regime_evidence); }},
      {.sweep = "error", .type = T::kText,
       .meaning = "why a failed or invalid point has no result (a guard's message, the scene's "
                  "refusal)",
       .null_when = "the point is `ok`",
       .get = [](S s) { return V::text(s.failure); }},
      {.python = "harmonic", .type = T::kFlag,
       .meaning = "an oscillation whose period the paper's formula reads (`oscillates`, "
                  "`clipped`, `grows`, `decays`)",
       .get = [](S s) { return V::flag(s.harmonic()); }},
      {.json = "wall_s", .python = "wall_s", .unit = "s", .meaning = "this machine's wall time",
       .get = [](S s) { return V::number(s.wall_s); }, .timing = true},
      {.json = "real_time_factor", .python = "real_time_factor",
       .meaning = "simulated time over wall time on this machine",
       .get = [](S s) { return V::number(s.real_time_factor); }, .timing = true},
      {.json = "steps_per_second", .python = "steps_per_second", .unit = "1/s",
       .meaning = "physics steps per second of wall time on this machine",
       .get = [](S s) { return V::number(s.steps_per_second); }, .timing = true},
  };
  // clang-format on
}

}  // namespace

const std::vector<SummaryField>& summary_fields() {
  static const std::vector<SummaryField> fields = [] {
    std::vector<SummaryField> all;
    for (auto* group : {&run_fields, &period_fields, &mu_k_fields, &rig_fields, &motion_fields,
                        &theory_fields, &numerics_fields}) {
      std::vector<SummaryField> part = group();
      all.insert(all.end(), part.begin(), part.end());
    }
    return all;
  }();
  return fields;
}

json summary_json(const RunSummary& summary) {
  json j = json::object();
  for (const SummaryField& f : summary_fields()) {
    if (f.json == nullptr || f.timing) continue;
    json value = f.get(summary).json();
    if (value.is_null() && f.omit_when_null) continue;
    j[f.json] = std::move(value);
  }
  return j;
}

json timing_json(const RunSummary& summary) {
  json j = json::object();
  for (const SummaryField& f : summary_fields())
    if (f.json != nullptr && f.timing) j[f.json] = f.get(summary).json();
  return j;
}

void fill_sweep_columns(json& row, const RunSummary& summary) {
  for (const SummaryField& f : summary_fields())
    if (f.sweep != nullptr) row[f.sweep] = f.get(summary).json();
}

std::vector<const char*> sweep_summary_columns() {
  std::vector<const char*> columns;
  for (const SummaryField& f : summary_fields())
    if (f.sweep != nullptr) columns.push_back(f.sweep);
  return columns;
}

}  // namespace fl
