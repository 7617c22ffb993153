#include "lab/compare/spacing_fit_report.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "io/csv_table.hpp"
#include "io/json_value.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

nlohmann::json summary_json(const std::optional<SampleSummary>& s) {
  if (!s) return nullptr;
  return {{"mean", s->mean},
          {"sd", json_or_null(s->sd)},
          {"quantile_025", s->quantile_025},
          {"quantile_975", s->quantile_975}};
}

nlohmann::json monte_carlo_json(const ThickPlateFitMonteCarlo& mc) {
  return {{"draws", mc.draws},
          {"seed", mc.seed},
          {"accepted", mc.accepted},
          {"skipped", mc.skipped},
          {"mu_k", summary_json(mc.mu_k)},
          {"h_c_m", summary_json(mc.h_c)},
          {"correlation", json_or_null(mc.correlation)}};
}

nlohmann::json rig_json(const FitThroughRig& rig) {
  const ThickPlateFit& f = rig.fit;
  return {{"scene", rig.scene},
          {"h_c_scene_m", rig.h_c_scene},
          {"mu_k_closed_form", json_or_null(rig.closed_form.mu_k)},
          {"mu_k", json_or_null(f.mu_k)},
          {"mu_k_err", json_or_null(f.mu_k_err)},
          {"h_c_m", json_or_null(f.h_c)},
          {"h_c_err_m", json_or_null(f.h_c_err)},
          {"correlation", json_or_null(f.correlation)},
          {"chi2", f.chi2},
          {"chi2_per_dof", json_or_null(f.chi2_per_dof)},
          {"mu_k_path", rig.mu_k_path},
          {"iterations", rig.iterations},
          {"resolution", rig.resolution},
          {"converged", rig.converged},
          {"simulations", rig.simulations}};
}

}  // namespace

SpacingFitReport fit_spacing_series(SpacingSeries series, double gravity) {
  SpacingFitReport report;
  report.fit = fit_thick_plate(series.measurements(), {.gravity = gravity});
  report.series = std::move(series);
  report.gravity = gravity;
  return report;
}

nlohmann::json spacing_fit_json(const SpacingFitReport& r) {
  const ThickPlateFit& f = r.fit;
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < r.series.rows.size(); ++i) {
    const SpacingSeriesRow& in = r.series.rows[i];
    const FitRow& out = f.rows[i];
    nlohmann::json row{
        {"line", in.line},
        {"label", r.series.has_label ? nlohmann::json(escape_invalid_utf8(in.label)) : nullptr},
        {"spacing_m", in.measurement.spacing},
        {"spacing_err_m", json_or_null(in.measurement.spacing_err)},
        {"period_s", in.measurement.period},
        {"period_err_s", in.measurement.period_err},
        {"period_squared_err_s2", out.period_squared_err},
        {"period_fit_s", json_or_null(out.period_fit)},
        {"residual_sigma", out.residual_sigma},
        {"mu_k_thin", out.mu_k_thin}};
    if (r.rig) {
      const FitThroughRigRow& rig = r.rig->rows[i];
      row["period_simulated_s"] = rig.period_simulated;
      row["period_simulated_source"] = rig.period_simulated_source;
      row["period_closed_form_s"] = rig.period_closed_form;
      row["correction"] = rig.correction;
      row["period_corrected_s"] = rig.period_corrected;
      row["residual_sigma_rig"] = r.rig->fit.rows[i].residual_sigma;
    }
    rows.push_back(std::move(row));
  }
  return {{"file", escape_invalid_utf8(r.series.file)},
          {"gravity_m_s2", r.gravity},
          {"rows_count", r.series.rows.size()},
          {"spacing_errors", r.series.has_spacing_err},
          {"slope_s2_per_m", f.slope},
          {"slope_err_s2_per_m", f.slope_err},
          {"intercept_s2", f.intercept},
          {"intercept_err_s2", f.intercept_err},
          {"slope_intercept_covariance", f.slope_intercept_covariance},
          {"mu_k", json_or_null(f.mu_k)},
          {"mu_k_err", json_or_null(f.mu_k_err)},
          {"h_c_m", json_or_null(f.h_c)},
          {"h_c_err_m", json_or_null(f.h_c_err)},
          {"correlation", json_or_null(f.correlation)},
          {"chi2", f.chi2},
          {"degrees_of_freedom", f.degrees_of_freedom},
          {"chi2_per_dof", json_or_null(f.chi2_per_dof)},
          {"effective_variance_iterations", f.iterations},
          {"effective_variance_converged", f.converged},
          {"spacing_without_restoring_force_m", json_or_null(spacing_without_restoring_force(f))},
          {"thin_slope_s2_per_m", f.thin_slope},
          {"mu_k_thin_line", f.mu_k_thin_line},
          {"mu_k_thin_line_err", f.mu_k_thin_line_err},
          {"thin_chi2", f.thin_chi2},
          {"thin_chi2_per_dof",
           f.rows.size() > 1 ? nlohmann::json(f.thin_chi2 / static_cast<double>(f.rows.size() - 1))
                             : nlohmann::json(nullptr)},
          {"rows", rows},
          {"monte_carlo", r.monte_carlo ? monte_carlo_json(*r.monte_carlo) : nullptr},
          {"through_rig", r.rig ? rig_json(*r.rig) : nullptr}};
}

std::string spacing_fit_csv(const SpacingFitReport& r) {
  std::string csv =
      "line,label,spacing_m,spacing_err_m,period_s,period_err_s,period_squared_err_s2,"
      "period_fit_s,residual_sigma,mu_k_thin";
  if (r.rig) csv += ",period_simulated_s,correction,period_corrected_s,residual_sigma_rig";
  csv += "\n";
  const auto number = [](const std::optional<double>& v) {
    return v && std::isfinite(*v) ? fmt::format("{}", *v) : std::string();
  };
  for (std::size_t i = 0; i < r.series.rows.size(); ++i) {
    const SpacingSeriesRow& in = r.series.rows[i];
    const FitRow& out = r.fit.rows[i];
    const std::string label = csv_cell(in.label);
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}", in.line, label, in.measurement.spacing,
                       number(in.measurement.spacing_err), in.measurement.period,
                       in.measurement.period_err, out.period_squared_err, number(out.period_fit),
                       out.residual_sigma, out.mu_k_thin);
    if (r.rig) {
      const FitThroughRigRow& rig = r.rig->rows[i];
      csv += fmt::format(",{},{},{},{}", rig.period_simulated, rig.correction, rig.period_corrected,
                         r.rig->fit.rows[i].residual_sigma);
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace fl
