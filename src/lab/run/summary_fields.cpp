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

// A spread of the estimator's periods, or null without two accepted periods to give one.
template <typename Get>
json from_estimator(const RunSummary& s, Get get) {
  return s.estimator && s.estimator->periods_used >= 2 ? json(get(*s.estimator)) : json(nullptr);
}

// Where mu_k came from when not from the rig's estimator (left out when it did).
json mu_k_source_json(const RunSummary& s) {
  if (!s.mu_k_source || *s.mu_k_source == PeriodSource::kHallEstimator) return nullptr;
  return json(s.estimator ? "trajectory: the rig's estimator accepted no period"
                          : "trajectory: the scene has no sensor");
}

json drive_json(const RunSummary& s) {
  if (!s.drive) return nullptr;
  const DriveReport& d = *s.drive;
  return json{{"motor_speed_rad_s", d.motor_speed},
              {"motor_torque_n_m", d.motor_torque},
              {"roller_speeds_rad_s", {d.roller_speeds[0], d.roller_speeds[1]}},
              {"gearbox_ratio", d.gearbox_ratio},
              {"turning_fraction", d.turning_fraction},
              {"speed_ratio", json_or_null(d.speed_ratio)},
              {"speed_ratio_error", json_or_null(d.speed_ratio_error)},
              {"senses_opposite", json_or_null(d.senses_opposite)},
              {"load_torque_n_m", d.load_torque}};
}

json paper_json(const RunSummary& s) {
  if (!s.paper_period || !s.paper_mu_k) return nullptr;
  return json{{"material", s.paper_material},
              {"period_s", s.paper_period->value},
              {"period_err_s", s.paper_period->uncertainty},
              {"mu_k", s.paper_mu_k->value},
              {"mu_k_err", s.paper_mu_k->uncertainty}};
}

json warming_window_json(const std::optional<WarmingWindow>& w) {
  if (!w) return nullptr;
  return json{{"periods", w->periods}, {"period_s", w->period}, {"mu_k", w->mu_k}};
}

json warming_json(const RunSummary& s) {
  if (!s.warming) return nullptr;
  const WarmingReport& w = *s.warming;
  return json{{"start_temperature_k", w.start_temperature},
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
              {"whole_run", warming_window_json(w.whole_run)}};
}

}  // namespace

const std::vector<SummaryField>& summary_fields() {
  using S = const RunSummary&;
  static const std::vector<SummaryField> fields{
      {"scene", nullptr, [](S s) { return json(s.scene); }},
      {"seed", "seed", [](S s) { return json(s.seed); }},
      {nullptr, "status", [](S s) { return json(s.failed() ? "failed" : "ok"); }},
      {"regime", "regime", [](S s) { return json(regime_name(s.regime)); }},
      {"regime_since_s", nullptr, [](S s) { return json(s.regime_since); }},
      {"period_withheld", nullptr, [](S s) { return json_or_null(s.period_withheld); }},
      {"failure", nullptr, [](S s) { return json_or_null(s.failure); }},
      {"interrupted_at_s", nullptr, [](S s) { return json_or_null(s.interrupted_at); }, true},
      {"estimator_disagreement", nullptr,
       [](S s) { return json_or_null(s.estimator_disagreement); }},
      {"condition_period", nullptr, [](S s) { return json(s.condition_period); }},
      {"condition_spacing", nullptr, [](S s) { return json(s.condition_spacing); }},
      {"condition_h_c", nullptr, [](S s) { return json(s.condition_h_c); }},
      {"period_s", "period_s", [](S s) { return json_or_null(s.period); }},
      {"period_std_s", "period_std_s",
       [](S s) {
         return from_estimator(s, [](const EstimatorReport& e) { return e.period_std; });
       }},
      {"period_std_error_s", "period_std_error_s",
       [](S s) {
         return from_estimator(s, [](const EstimatorReport& e) { return e.period_std_error; });
       }},
      {"periods_used", "periods_used",
       [](S s) { return s.estimator ? json(s.estimator->periods_used) : json(nullptr); }},
      {"periods_discarded", "periods_discarded",
       [](S s) { return s.estimator ? json(s.estimator->periods_discarded) : json(nullptr); }},
      {"period_trajectory_s", "period_trajectory_s",
       [](S s) { return json_or_null(s.period_trajectory); }},
      {"period_trajectory_err_s", nullptr,
       [](S s) { return json_or_null(s.period_trajectory_err); }},
      {"oscillation_centre_m", "oscillation_centre_m",
       [](S s) { return json_or_null(s.oscillation_centre); }},
      {"oscillation_centre_theory_m", "oscillation_centre_theory_m",
       [](S s) { return json_or_null(s.oscillation_centre_theory); }},
      {"drift_speed_m_s", "drift_speed_m_s", [](S s) { return json_or_null(s.drift_speed); }},
      {"drift_speed_theory_m_s", "drift_speed_theory_m_s",
       [](S s) { return json_or_null(s.drift_speed_theory); }},
      {"tilt_rad", nullptr, [](S s) { return json(s.tilt); }},
      {"period_thin_s", "period_thin_s", [](S s) { return json_or_null(s.period_thin); }},
      {"period_thick_s", "period_thick_s", [](S s) { return json_or_null(s.period_thick); }},
      {"error_vs_thin", "error_vs_thin",
       [](S s) { return json_or_null(relative_error(s.period, s.period_thin)); }},
      {"error_vs_thick", "error_vs_thick",
       [](S s) { return json_or_null(relative_error(s.period, s.period_thick)); }},
      {"trajectory_error_vs_thick", nullptr,
       [](S s) { return json_or_null(relative_error(s.period_trajectory, s.period_thick)); }},
      {"mu_k_set", "mu_k_set", [](S s) { return json_or_null(s.mu_k_set); }},
      {"mu_k_recovered", "mu_k_recovered", [](S s) { return json_or_null(s.mu_k_recovered); }},
      {"mu_k_source", "mu_k_source", mu_k_source_json, true},
      {"mu_k_recovered_thick", "mu_k_recovered_thick",
       [](S s) { return json_or_null(s.mu_k_recovered_thick); }},
      {"mu_k_estimator", nullptr, [](S s) { return json_or_null(s.mu_k_estimator); }, true},
      {"mu_k_err_worst", "mu_k_err_worst", [](S s) { return json_or_null(s.mu_k_err_worst); },
       true},
      {"mu_k_err_quadrature", "mu_k_err_quadrature",
       [](S s) { return json_or_null(s.mu_k_err_quadrature); }, true},
      {"predicted_integrator_bias", nullptr,
       [](S s) { return json_or_null(s.predicted_integrator_bias); }},
      {"sensor_clock_error", nullptr, [](S s) { return json_or_null(s.clock_error); }, true},
      {"clock_mu_k_bias", nullptr,
       [](S s) {
         return s.clock_error ? json(1.0 / ((1.0 + *s.clock_error) * (1.0 + *s.clock_error)) - 1.0)
                              : json(nullptr);
       },
       true},
      {"runout_m", "runout_m", [](S s) { return json_or_null(s.runout); }, true},
      {"runout_threshold_m", "runout_threshold_m",
       [](S s) { return json_or_null(s.runout_threshold); }, true},
      {"spacing_m", "spacing_m", [](S s) { return json_or_null(s.spacing); }},
      {"h_c_m", "h_c_m", [](S s) { return json_or_null(s.h_c); }},
      {"plate_mass_kg", nullptr, [](S s) { return json_or_null(s.plate_mass); }},
      {nullptr, "temperature_k", [](S s) { return json_or_null(s.temperature); }},
      {nullptr, "gravity_m_s2", [](S s) { return json_or_null(s.gravity); }},
      {"roller_speed_rad_s", "roller_speed_rad_s",
       [](S s) { return json_or_null(s.roller_speed); }},
      {"roller_speed_1_rad_s", "roller_speed_1_rad_s",
       [](S s) { return json_or_null(s.roller_speed_1); }},
      {"drive", nullptr, drive_json},
      {"plate_speed_max_m_s", nullptr, [](S s) { return json_or_null(s.plate_speed_max); }},
      {"slip_margin", "slip_margin", [](S s) { return json_or_null(s.slip_margin); }},
      {nullptr, "slip_threshold_rad_s", [](S s) { return json_or_null(s.slip_threshold); }},
      {"amplitude_start_m", "amplitude_start_m",
       [](S s) { return json_or_null(s.amplitude_start); }},
      {"amplitude_end_m", "amplitude_end_m", [](S s) { return json_or_null(s.amplitude_end); }},
      {"amplitude_drift_per_period", nullptr,
       [](S s) { return json_or_null(s.amplitude_drift_per_period); }},
      {"clip_time_s", "clip_time_s", [](S s) { return json_or_null(s.clip_time); }, true},
      {"amplitude_before_clip_m", nullptr,
       [](S s) { return json_or_null(s.amplitude_before_clip); }, true},
      {"amplitude_clipped_m", "amplitude_clipped_m",
       [](S s) { return json_or_null(s.amplitude_clipped); }, true},
      {"stick_slip_period_s", "stick_slip_period_s",
       [](S s) { return json_or_null(s.stick_slip_period); }, true},
      {"stick_slip_amplitude_m", "stick_slip_amplitude_m",
       [](S s) { return json_or_null(s.stick_slip_amplitude); }, true},
      {"stick_duration_s", nullptr, [](S s) { return json_or_null(s.stick_duration); }, true},
      {"growth_rate_per_s", "growth_rate_per_s", [](S s) { return json_or_null(s.growth_rate); },
       true},
      {"e_folding_time_s", nullptr, [](S s) { return json_or_null(s.e_folding_time); }, true},
      {"jumps", "jumps", [](S s) { return s.jumps ? json(*s.jumps) : json(nullptr); }, true},
      {"first_jump_time_s", nullptr, [](S s) { return json_or_null(s.first_jump_time); }, true},
      {"longest_jump_s", nullptr, [](S s) { return json_or_null(s.longest_jump); }, true},
      {"highest_jump_m", "highest_jump_m", [](S s) { return json_or_null(s.highest_jump); }, true},
      {"regime_theory", nullptr,
       [](S s) { return s.regime_theory ? json(regime_name(*s.regime_theory)) : json(nullptr); },
       true},
      {"amplitude_clipped_theory_m", nullptr,
       [](S s) { return json_or_null(s.amplitude_clipped_theory); }, true},
      {"stick_slip_period_theory_s", nullptr,
       [](S s) { return json_or_null(s.stick_slip_period_theory); }, true},
      {"stick_slip_amplitude_theory_m", nullptr,
       [](S s) { return json_or_null(s.stick_slip_amplitude_theory); }, true},
      {"stick_duration_theory_s", nullptr,
       [](S s) { return json_or_null(s.stick_duration_theory); }, true},
      {"growth_rate_theory_per_s", nullptr, [](S s) { return json_or_null(s.growth_rate_theory); },
       true},
      {"warming", nullptr, warming_json, true},
      {"paper", nullptr, paper_json, true},
      {nullptr, "paper_material",
       [](S s) { return s.paper_period ? json(s.paper_material) : json(nullptr); }},
      {nullptr, "paper_period_s",
       [](S s) { return s.paper_period ? json(s.paper_period->value) : json(nullptr); }},
      {nullptr, "paper_period_err_s",
       [](S s) { return s.paper_period ? json(s.paper_period->uncertainty) : json(nullptr); }},
      {nullptr, "paper_mu_k",
       [](S s) { return s.paper_mu_k ? json(s.paper_mu_k->value) : json(nullptr); }},
      {nullptr, "paper_mu_k_err",
       [](S s) { return s.paper_mu_k ? json(s.paper_mu_k->uncertainty) : json(nullptr); }},
      {"min_normal_force_n", nullptr, [](S s) { return json_or_null(s.min_normal_force); }},
      {"max_penetration_m", nullptr, [](S s) { return json_or_null(s.max_penetration); }},
      {"time_step_s", "time_step_s", [](S s) { return json_or_null(s.time_step); }},
      {"solver_iterations", nullptr, [](S s) { return json(s.solver_iterations); }},
      {"solver_iterations_raised", nullptr,
       [](S s) { return json_or_null(s.solver_iterations_raised); }, true},
      {"duration_s", "duration_s", [](S s) { return json_or_null(s.duration); }},
      {"steps", "steps", [](S s) { return json(s.steps); }},
      {"regime_evidence", "regime_detail", [](S s) { return json(s.regime_evidence); }},
      {nullptr, "error", [](S s) { return json_or_null(s.failure); }},
  };
  return fields;
}

json summary_json(const RunSummary& summary) {
  json j = json::object();
  for (const SummaryField& f : summary_fields()) {
    if (f.summary_key == nullptr) continue;
    json value = f.get(summary);
    if (value.is_null() && f.omit_when_null) continue;
    j[f.summary_key] = std::move(value);
  }
  return j;
}

void fill_sweep_columns(json& row, const RunSummary& summary) {
  for (const SummaryField& f : summary_fields())
    if (f.sweep_column != nullptr) row[f.sweep_column] = f.get(summary);
}

std::vector<const char*> sweep_summary_columns() {
  std::vector<const char*> columns;
  for (const SummaryField& f : summary_fields())
    if (f.sweep_column != nullptr) columns.push_back(f.sweep_column);
  return columns;
}

}  // namespace fl
