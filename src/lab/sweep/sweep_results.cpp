#include "lab/sweep/sweep_results.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "io/csv_table.hpp"
#include "io/field_ref.hpp"
#include "lab/run/cycle_report.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/step_choice.hpp"
#include "lab/run/summary_fields.hpp"

namespace fl {
namespace {

// The row's columns after the index and the axes, in CSV order: the run's fields from the one
// table of summary fields. Every row has every key (null when the point has no such value).
const std::vector<std::string>& fixed_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> names;
    for (const char* c : sweep_summary_columns()) names.emplace_back(c);
    // What sized the point's step, when the sweep has an accuracy (lab/run/step_choice.hpp).
    names.emplace_back("time_step_basis");
    return names;
  }();
  return columns;
}

nlohmann::json empty_row(const SweepSpec& spec, const SweepPoint& point) {
  nlohmann::json row;
  for (const std::string& c : fixed_columns()) row[c] = nullptr;
  row["index"] = point.index;
  nlohmann::json params = nlohmann::json::object();
  const auto axes = spec.axes();
  for (std::size_t i = 0; i < axes.size(); ++i) params[axes[i]->name] = point.labels[i];
  row["params"] = params;
  nlohmann::json set = nlohmann::json::array();
  for (const SceneOverride& o : point.overrides) set.push_back(o.path + "=" + o.value);
  row["set"] = set;
  return row;
}

// A JSON value as a CSV cell: null empty, numbers as the shortest text that reads back.
std::string json_csv_cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_unsigned()) return std::to_string(v.get<std::uint64_t>());
  if (v.is_number_integer()) return std::to_string(v.get<std::int64_t>());
  if (v.is_number_float()) return fmt::format("{}", v.get<double>());
  return csv_cell(v.is_string() ? v.get<std::string>() : v.dump());
}

}  // namespace

PointResult run_sweep_point(const SweepSpec& spec, const SweepPoint& point,
                            const SceneInputs& inputs) {
  const auto start = std::chrono::steady_clock::now();
  PointResult out;
  out.index = point.index;
  out.row = empty_row(spec, point);
  std::optional<Scene> scene;
  try {
    scene = load_scene_text(spec.scene_text, spec.scene_file, point.overrides, inputs.paper,
                            inputs.parts);
  } catch (const std::exception& e) {
    out.row["status"] = "invalid";
    out.row["error"] = plain_fields(e.what());
  }
  if (scene) {
    out.row["seed"] = scene->world.seed;
    try {
      CompiledRig rig = compile_rig(*scene);
      // Only the trajectory's period asked for: no Hall signal to simulate (nor its error to
      // leave room for in the step).
      if (!spec.hall) rig.sensor.reset();
      if (spec.accuracy) {
        const StepChoice step = step_for_accuracy_or_scene(rig, *spec.accuracy);
        rig = with_time_step(std::move(rig), step.time_step);
        out.row["time_step_basis"] = step_basis_name(step.basis);
      }
      RunOptions options;
      options.record_cycles = spec.cycles;
      RunRecording recording;
      const RunSummary summary = run_experiment(rig, options, &recording);
      fill_sweep_columns(out.row, summary);
      if (spec.cycles) out.cycles_csv = cycles_csv(rig, recording.cycles);
    } catch (const std::exception& e) {
      out.row["status"] = "failed";
      out.row["error"] = "the run stopped: " + plain_fields(e.what());
    }
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// The run's columns a sweep writes after its axes: all but those an axis already is (a seeds
// axis is the seed column).
std::vector<std::string> run_columns(const nlohmann::json& plan) {
  std::vector<std::string> out;
  for (const std::string& c : fixed_columns()) {
    bool axis = false;
    for (const nlohmann::json& a : plan.at("axes")) axis = axis || a.at("name") == c;
    if (!axis) out.push_back(c);
  }
  return out;
}

std::vector<std::string> sweep_result_columns(const nlohmann::json& plan) {
  std::vector<std::string> columns{"index"};
  for (const nlohmann::json& a : plan.at("axes"))
    columns.push_back(a.at("name").get<std::string>());
  const std::vector<std::string> run = run_columns(plan);
  columns.insert(columns.end(), run.begin(), run.end());
  return columns;
}

std::string sweep_results_csv(const nlohmann::json& plan, const std::vector<nlohmann::json>& rows) {
  const std::vector<std::string> columns = sweep_result_columns(plan);
  const std::size_t axes = plan.at("axes").size();
  std::string csv;
  for (std::size_t i = 0; i < columns.size(); ++i) csv += (i ? "," : "") + csv_cell(columns[i]);
  csv += '\n';
  for (const nlohmann::json& row : rows) {
    csv += json_csv_cell(row.at("index"));
    for (std::size_t a = 0; a < axes; ++a)
      csv += "," + json_csv_cell(row.at("params").at(columns[1 + a]));
    for (const std::string& c : run_columns(plan))
      csv += "," + json_csv_cell(row.value(c, nlohmann::json()));
    csv += '\n';
  }
  return csv;
}

nlohmann::json sweep_results_json(const nlohmann::json& plan,
                                  const std::vector<nlohmann::json>& rows) {
  std::map<std::string, int> status{{"ok", 0}, {"invalid", 0}, {"failed", 0}};
  std::map<std::string, int> regimes;
  for (const nlohmann::json& row : rows) {
    ++status[row.value("status", "failed")];
    if (row.contains("regime") && row["regime"].is_string())
      ++regimes[row["regime"].get<std::string>()];
  }
  return nlohmann::json{{"format", 1},
                        {"sweep", plan["sweep"]},
                        {"scene", plan["scene"]},
                        {"points", rows.size()},
                        {"columns", sweep_result_columns(plan)},
                        {"axes", plan["axes"]},
                        {"status", status},
                        {"regimes", regimes},
                        {"rows", rows}};
}

std::string point_file_text(const PointResult& result, const std::string& plan_digest) {
  nlohmann::json j{{"plan", plan_digest},
                   {"index", result.index},
                   {"row", result.row},
                   {"wall_s", result.wall_s}};
  if (!result.cycles_csv.empty()) j["cycles"] = result.cycles_csv;
  return j.dump() + "\n";
}

std::optional<PointResult> parse_point_file(const std::string& text,
                                            const std::string& plan_digest) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("plan", "") != plan_digest ||
      !j.contains("index") || !j["index"].is_number_unsigned() || !j.contains("row") ||
      !j["row"].is_object())
    return std::nullopt;
  PointResult r;
  r.index = j["index"].get<std::size_t>();
  r.row = j["row"];
  r.wall_s = j.value("wall_s", 0.0);
  if (j.contains("cycles") && j["cycles"].is_string())
    r.cycles_csv = j["cycles"].get<std::string>();
  return r;
}

}  // namespace fl
