#include "lab/request/fit_request.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "core/plausible_range.hpp"
#include "io/atomic_file.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/material_fields.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl {
namespace {

// What the fit says that a friction oscillator's series cannot: refused as bad input, saying so
// rather than giving a mu_k that means nothing.
void require_physical(const SpacingFitReport& r) {
  const ThickPlateFit& f = r.fit;
  const SpacingSeries& s = r.series;
  if (!f.mu_k)
    throw InputError(
        SourceLocation{s.file, 0, 0},
        fmt::format("expected T^2 to grow with the spacing (T^2 = 2 pi^2 l / (mu_k g) - 4 pi^2 "
                    "h_c / g), found it falling: slope {:.4g} +- {:.2g} s^2/m, so no positive "
                    "mu_k fits these rows; check that the spacing and period columns hold what "
                    "their names say, in the units written",
                    f.slope, f.slope_err));
  // Rows each within a rig's range can still lie on a line no rig gives.
  if (const std::optional<std::string> why = implausible(*f.mu_k, kMuKRange))
    throw InputError(SourceLocation{s.file, 0, 0},
                     fmt::format("the fitted line's slope {:.4g} s^2/m gives a mu_k no rig has: "
                                 "{}; check that the spacing and period columns hold what their "
                                 "names say, in the units written",
                                 f.slope, *why));
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    if (f.rows[i].period_fit) continue;
    throw InputError(
        s.at(i, SeriesColumn::kSpacing),
        fmt::format("the fitted line leaves no restoring force at this spacing: l = {:.1f} mm <= "
                    "2 mu_k h_c = {:.1f} mm (mu_k = {:.4g}, h_c = {:.2f} mm), where no plate "
                    "oscillates; the rows do not lie on one thick-plate line (this row's "
                    "residual is {:+.1f} sd): check its values, or measure at larger spacings",
                    s.rows[i].measurement.spacing * 1e3, *spacing_without_restoring_force(f) * 1e3,
                    *f.mu_k, *f.h_c * 1e3, f.rows[i].residual_sigma));
  }
}

}  // namespace

Outcome FitResult::outcome() const {
  if (!rig_failure.empty()) return Outcome::kFailed;
  if (!plot_failure.empty()) return Outcome::kIncomplete;
  return Outcome::kDone;
}

FitResult fit_series(const FitRequest& r) {
  FieldChecks checks;
  const double gravity = checks.positive(r.gravity, Dimension::kAcceleration, "gravity", "g");
  if (r.mc && (*r.mc < 1 || *r.mc > kMaxMonteCarloDraws))
    checks.problem(
        "monte_carlo.draws", std::to_string(*r.mc),
        fmt::format("expected the number of draws, a whole number from 1 to {} (e.g. "
                    "{}), found {}",
                    kMaxMonteCarloDraws, field_ref("monte_carlo.draws", "100000"), *r.mc));
  if (!r.through_rig && (!r.scene.file.empty() || !r.set.empty()))
    checks.problem(!r.scene.file.empty() ? "scene" : "set",
                   field_ref("scene") + " and " + field_ref("set") + " name the rig " +
                       field_ref("through_rig") + " simulates; add " + field_ref("through_rig"));
  std::string png;
  if (r.plot) {
    if (!r.plot->empty())
      png = *r.plot;
    else if (!r.out.empty())
      png = (std::filesystem::path(r.out) / "fit.png").string();
    else
      checks.problem("plot", "expected a PNG to draw (" + field_ref("plot", "fit.png") + "), or " +
                                 field_ref("out") + " for its fit.png; found neither");
  }
  const std::vector<SceneOverride> overrides = read_overrides(r.set, checks);
  const PaperTable& paper = paper_table_in(asset_dir(r.assets));
  const MaterialChoice material = read_material_fields(checks, paper, r.material, r.temperature);
  checks.throw_if_any();
  // Output places are checked before any work; a plot that fails still leaves the results. None
  // may replace the series (nor the scene it is fitted through).
  const std::vector<InputFile> inputs = {{r.series, "the series"},
                                         {r.through_rig ? r.scene.file : "", "the scene"}};
  refuse_overwriting_inputs(png, "plot", inputs);
  refuse_overwriting_inputs(r.out, {"fit.csv", "fit.json"}, "out", inputs);
  if (!r.out.empty()) prepare_output_folder(r.out, "out");
  if (!png.empty()) prepare_output_file(png, "plot");

  FitResult result;
  SpacingSeries series = read_spacing_series(r.series);
  result.warnings = series.warnings;
  if (series.rows_left_out > 0)
    result.warnings.push_back(fmt::format(
        "{}: {} row{} left out: {}", series.file, series.rows_left_out,
        series.rows_left_out == 1 ? "" : "s",
        series.sweep_results ? "points that failed or whose estimator accepted no period"
                             : "logs that gave no period (status other than ok)"));
  result.warnings.insert(result.warnings.end(), checks.warnings().begin(), checks.warnings().end());
  result.report = fit_spacing_series(std::move(series), gravity);
  SpacingFitReport& report = result.report;
  require_physical(report);
  if (r.mc)
    report.monte_carlo = thick_plate_fit_monte_carlo(
        report.series.measurements(), {.gravity = gravity},
        MonteCarloRequest{.draws = static_cast<int>(*r.mc), .seed = r.seed, .keep_samples = true});
  if (r.through_rig) {
    SceneSource source = r.scene;
    if (source.file.empty() && source.text.empty())
      source.file = shipped_scene("scenes/minimal.yaml");
    source.overrides.insert(source.overrides.end(), overrides.begin(), overrides.end());
    FitThroughRigRequest rig{.scene = *load_scene_source(std::move(source)).scene,
                             .gravity = gravity};
    rig.workers = r.jobs;
    try {
      report.rig = fit_through_rig(report.series.measurements(), rig);
    } catch (const FitThroughRigError& e) {
      result.rig_failure = e.what();
    }
  }

  result.paper = paper_value_for(paper, material, {}, *report.fit.mu_k, *report.fit.mu_k_err);
  result.json = spacing_fit_json(report);
  result.json["paper"] =
      result.paper ? paper_comparison_json(*result.paper) : nlohmann::json(nullptr);
  std::string written_json;
  if (!r.out.empty()) {
    written_json = (std::filesystem::path(r.out) / "fit.json").string();
    const std::string csv = (std::filesystem::path(r.out) / "fit.csv").string();
    write_file_atomic(csv, spacing_fit_csv(report));
    write_file_atomic(written_json, result.json.dump(1) + "\n");
    result.written = {csv, written_json};
  }
  if (!png.empty()) {
    try {
      // The plot's data: fit.json where it was written, else a temporary copy.
      if (!written_json.empty())
        run_plot_script("plot_fit.py", {written_json, png});
      else
        run_plot_script_on("plot_fit.py", result.json, png);
      result.written.push_back(png);
      result.plot = png;
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

}  // namespace fl
