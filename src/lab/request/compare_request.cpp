#include "lab/request/compare_request.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "core/paper_table.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/log_sidecar.hpp"
#include "io/atomic_file.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/logs/checked_reading.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/material_fields.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "lab/request/scene_source.hpp"
#include "text/utf8.hpp"

namespace fl {

int CompareRequestResult::rows_without_result() const {
  // The paper's own table shows the rows the model cannot oscillate (flexible foam at 300 K):
  // only your own rows must each give a result.
  if (!table || paper) return 0;
  return table->rows_without_result(refit_asked);
}

Outcome CompareRequestResult::outcome() const {
  if (interrupted) return Outcome::kInterrupted;
  if (rows_without_result() > 0) return Outcome::kFailed;
  if (!plot_failure.empty()) return Outcome::kIncomplete;
  return Outcome::kDone;
}

namespace {

// The plot of a comparison's file drawn by its script into `png`; a plot that cannot be drawn is
// the result's plot failure, the comparison kept.
void draw_plot(const char* script, const std::string& data, const std::string& png,
               CompareRequestResult& result) {
  try {
    run_plot_script(script, {data, png});
    result.written.push_back(png);
  } catch (const std::runtime_error& e) {
    result.plot_failure = e.what();
  }
}

// One Hall log against its simulation: the refit, the paper's value for the log's material, the
// report and its traces written, and the plot.
void compare_one_log(const CompareRequest& r, const HallLogOptions& reading,
                     fl_estimator::Geometry geometry, const PaperTable& paper,
                     const MaterialChoice& material, const CompareOptions& options,
                     CompareRequestResult& result) {
  const HallLog log = read_hall_log_checked(r.log, reading, LogSetUp{});
  // The sidecar's material (checked against the paper's table) when the request names none.
  const std::optional<LogSidecar> sidecar = read_log_sidecar(log.file, &paper);
  result.log = compare_log_with_rig(log, geometry, options);
  if (result.log->interrupted) {
    result.interrupted = true;
    return;
  }
  result.json = log_against_rig_json(*result.log);
  const CompareRow& row = result.log->fit.rows.front();
  if (row.mu_k_refit && row.mu_k_refit_err_quadrature)
    result.paper_value = paper_value_for(
        paper, material,
        sidecar ? MaterialChoice{sidecar->material, sidecar->temperature} : MaterialChoice{},
        *row.mu_k_refit, *row.mu_k_refit_err_quadrature);
  result.json["paper"] =
      result.paper_value ? paper_comparison_json(*result.paper_value) : nlohmann::json(nullptr);
  const std::string report = r.out + "/compare-log.json";
  const std::string traces = r.out + "/compare-log-traces.json";
  write_file_atomic(report, result.json.dump(1) + "\n");
  write_file_atomic(traces, log_against_rig_plot_data(*result.log).dump() + "\n");
  result.written = {report, traces};
  if (r.plot) draw_plot("plot_log_vs_sim.py", traces, r.out + "/compare-log.png", result);
}

// A table of measurements, each row simulated in its own rig: the table, the rows it left out,
// its files and the plot.
void compare_table(const CompareRequest& r, const MeasuredRows& measured,
                   const CompareOptions& options, CompareRequestResult& result) {
  result.table = run_compare(measured, options);
  result.interrupted = result.table->rows_interrupted() > 0;
  result.skipped = measured.skipped;
  result.json = compare_json(*result.table);
  // Rows of a table of logs whose log gave no period: left out, and said.
  nlohmann::json skipped = nlohmann::json::array();
  for (const SkippedRow& row : measured.skipped)
    skipped.push_back({{"label", escape_invalid_utf8(row.label)},
                       {"line", row.where.line},
                       {"reason", escape_invalid_utf8(row.reason)}});
  result.json["skipped"] = skipped;
  const std::string csv = r.out + "/compare.csv";
  const std::string json = r.out + "/compare.json";
  write_file_atomic(csv, compare_csv(*result.table));
  write_file_atomic(json, result.json.dump(1) + "\n");
  result.written = {csv, json};
  if (r.plot && !result.interrupted)
    draw_plot("plot_compare.py", json, r.out + "/compare.png", result);
}

}  // namespace

CompareRequestResult compare_measurements(const CompareRequest& r,
                                          std::function<void(std::size_t, std::size_t)> progress,
                                          const JobControl& control) {
  FieldChecks checks;
  const bool with_log = !r.log.empty();
  if (!with_log && (!r.geometry.empty() || !r.columns.empty() || r.rate || !r.time_unit.empty()))
    checks.problem(!r.geometry.empty()  ? "geometry"
                   : !r.columns.empty() ? "columns"
                   : r.rate             ? "rate"
                                        : "time_unit",
                   field_ref("geometry") + ", " + field_ref("columns") + ", " + field_ref("rate") +
                       " and " + field_ref("time_unit") + " say how to read a log; they go with " +
                       field_ref("log"));
  if (with_log && !r.measured.empty())
    checks.problem("log", r.log,
                   field_ref("log") + " compares one Hall log with its simulation, " +
                       field_ref("measured") + " a table of periods; give one");
  if (r.jobs < 0)
    checks.problem("jobs", std::to_string(r.jobs),
                   "expected a positive number of rows at once, found " + std::to_string(r.jobs));
  HallLogOptions reading;
  reading.columns = r.columns;
  reading.time_unit = r.time_unit;
  if (r.rate) reading.rate_hz = checks.quantity(*r.rate, Dimension::kFrequency, "rate");
  const std::optional<fl_estimator::Geometry> geometry =
      geometry_from_option(r.geometry.empty() ? "auto" : r.geometry);
  if (!geometry)
    checks.problem("geometry", r.geometry,
                   "expected auto, one or pair, found \"" + r.geometry + "\"");
  if (!with_log && (r.material || r.temperature))
    checks.problem(r.material ? "material" : "temperature",
                   field_ref("material") + " and " + field_ref("temperature") + " go with " +
                       field_ref("log") + "; the rows of a table name their own materials");
  const std::string assets = asset_dir(r.assets);
  const PaperTable& paper = paper_table_in(assets);
  const MaterialChoice material = read_material_fields(checks, paper, r.material, r.temperature);
  std::vector<SceneOverride> overrides = read_overrides(r.set, checks);
  if (r.duration) checks.quantity(*r.duration, Dimension::kTime, "duration");
  checks.throw_if_any();

  CompareRequestResult result;
  result.refit_asked = r.refit;
  result.paper = r.measured.empty() && !with_log;
  const MeasuredRows measured =
      with_log ? MeasuredRows{}
               : read_measured_rows(result.paper ? paper_measurements_path(assets) : r.measured);
  CompareOptions options;
  options.scene_file = r.scene.empty() ? shipped_scene("scenes/paper-rig.yaml") : r.scene;
  const SceneInputs inputs = scene_inputs(assets);
  options.paper = inputs.paper;
  options.parts = inputs.parts;
  for (SceneOverride& over : overrides) {
    // What the comparison or the rows set would silently win over the request's own key.
    const bool duration = over.path == "world.duration";
    const bool by_rows =
        std::any_of(measured.rows.begin(), measured.rows.end(), [&](const auto& row) {
          return std::any_of(row.keys.begin(), row.keys.end(),
                             [&](const SceneOverride& k) { return k.path == over.path; });
        });
    // With a log, mu_k is where the refit starts (the scene's own otherwise).
    const bool start_mu_k = with_log && over.path == "friction.mu_k";
    if ((compare_sets_key(over.path) && !start_mu_k) || by_rows)
      checks.problem(
          "set", over.path + "=" + over.value,
          fmt::format("expected a key compare leaves to the scene, found {}, which {}; {}",
                      over.path,
                      by_rows ? "rows of " + measured.file + " set for themselves"
                              : "compare sets for each row (mu_k by the refit, and the run's "
                                "length)",
                      duration ? "use " + field_ref("duration") + " instead"
                               : "drop it, or simulate that set-up with a run"));
    options.overrides.push_back(std::move(over));
  }
  checks.throw_if_any();
  if (r.duration) {
    options.overrides.push_back({"world.duration", quantity_input_text(*r.duration)});
    options.min_periods = 0;
  }
  // Its files may replace none it reads.
  refuse_overwriting_inputs(
      r.out,
      with_log ? std::vector<std::string>{"compare-log.json", "compare-log-traces.json",
                                          "compare-log.png"}
               : std::vector<std::string>{"compare.csv", "compare.json", "compare.png"},
      "out",
      {{r.measured, "the measurements"}, {r.log, "the log"}, {options.scene_file, "the scene"}});
  prepare_output_folder(r.out, "out");
  options.workers = r.jobs;
  options.refit = r.refit;
  options.progress = std::move(progress);
  options.control = control;

  if (with_log)
    compare_one_log(r, reading, *geometry, paper, material, options, result);
  else
    compare_table(r, measured, options, result);
  return result;
}

}  // namespace fl
