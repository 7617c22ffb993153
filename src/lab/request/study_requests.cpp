#include "lab/request/study_requests.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl {
namespace {

std::string accuracy_csv(const AccuracyStudy& study) {
  std::string csv =
      "time_step_s,solver_iterations,period_s,period_error,predicted_error,amplitude_drift_per_"
      "period,"
      "wall_per_simulated_second_s,valid\n";
  for (const AccuracyPoint& p : study.points) {
    csv += fmt::format("{},{},{},{},{},{},{},{}\n", p.time_step, p.solver_iterations, p.period,
                       p.period_error, p.predicted_error, p.amplitude_drift,
                       p.wall_per_simulated_second, p.valid ? 1 : 0);
  }
  return csv;
}

nlohmann::json row_json(const StabilityRow& r) {
  return {{"case", r.name},
          {"parameters", r.parameters},
          {"expected", regime_name(r.expected)},
          {"expected_reason", r.expected_reason},
          {"declared", r.declared ? regime_name(*r.declared) : ""},
          {"found", regime_name(r.found)},
          {"evidence", r.evidence},
          {"solver_iterations", r.solver_iterations},
          {"solver_iterations_raised", json_or_null(r.solver_iterations_raised)},
          {"as_expected", r.as_expected},
          {"largest_step_s", json_or_null(r.largest_step)},
          {"step_note", r.step_note},
          {"period_error", json_or_null(r.period_error)},
          {"condition_period", r.condition_period},
          {"condition_spacing", r.condition_spacing},
          {"wall_s", r.wall_s}};
}

}  // namespace

nlohmann::json AccuracyResult::json() const {
  nlohmann::json j{{"scene", scene},
                   {"period_thick_s", study.period_thick},
                   {"omega_rad_s", study.omega},
                   {"csv", written.empty() ? std::string() : written.front()}};
  if (study.law) {
    j["law"] = {{"coefficient", study.law->coefficient},
                {"exponent", study.law->exponent},
                {"points", study.law->points},
                {"theory_coefficient", 1.0 / 24.0},
                {"theory_exponent", 2.0}};
  }
  return j;
}

Outcome AccuracyResult::outcome() const {
  if (study.interrupted) return Outcome::kInterrupted;
  return plot_failure.empty() ? Outcome::kDone : Outcome::kIncomplete;
}

AccuracyResult study_accuracy(const AccuracyRequest& r, const JobControl& control) {
  FieldChecks checks;
  // The study sets each point's length (periods), step and solver iterations itself.
  if (r.duration)
    checks.problem("duration", "each point simulates " + field_ref("periods") +
                                   " periods of the thick-plate period; give " +
                                   field_ref("periods", "N") + " instead");
  if (r.periods < 3 || r.periods > 1000)
    checks.problem("periods", std::to_string(r.periods),
                   "expected 3 to 1000 periods per point, found " + std::to_string(r.periods));
  std::vector<SceneOverride> overrides = read_overrides(r.set, checks);
  for (const SceneOverride& o : overrides)
    if (o.path == "world.duration" || o.path == "world.time_step" ||
        o.path == "world.solver_iterations")
      checks.problem("set", o.path + "=" + o.value,
                     "the study sets " + o.path +
                         " for each point of its grid, so this would be ignored; drop it (the "
                         "length is " +
                         field_ref("periods") + ")");
  checks.throw_if_any();
  SceneSource source = r.scene;
  source.overrides.insert(source.overrides.end(), overrides.begin(), overrides.end());
  const LoadedScene scene = load_scene_source(std::move(source));
  refuse_overwriting_inputs(r.out, {"accuracy.csv", "accuracy.json", "accuracy.png"}, "out",
                            {{r.scene.file, "the scene"}});
  prepare_output_folder(r.out, "out");

  AccuracyResult result;
  result.scene = scene.scene->name;
  result.periods = r.periods;
  AccuracyGrid grid;
  grid.periods = r.periods;
  result.study = run_accuracy_study(*scene.scene, grid, control);
  const std::string csv = r.out + "/accuracy.csv";
  const std::string json = r.out + "/accuracy.json";
  write_file_atomic(csv, accuracy_csv(result.study));
  result.written = {csv, json};
  write_file_atomic(json, result.json().dump(2) + "\n");
  if (r.plot && !result.study.interrupted) {
    const std::string png = r.out + "/accuracy.png";
    try {
      run_plot_script("plot_accuracy.py", {csv, json, png});
      result.written.push_back(png);
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

std::string default_stability_dir() {
  return (std::filesystem::path(tools_dir()).parent_path() / "scenes" / "extreme").string();
}

int StabilityResult::unexpected() const {
  return static_cast<int>(std::count_if(rows.begin(), rows.end(),
                                        [](const StabilityRow& r) { return !r.as_expected; }));
}

nlohmann::json StabilityResult::json() const {
  nlohmann::json all = nlohmann::json::array();
  for (const StabilityRow& r : rows) all.push_back(row_json(r));
  return {{"cases", all}, {"unexpected", unexpected()}};
}

Outcome StabilityResult::outcome() const {
  const Outcome cases = unexpected() == 0 ? Outcome::kDone : Outcome::kFailed;
  return not_run > 0 ? worse(cases, Outcome::kInterrupted) : cases;
}

StabilityResult study_stability(const StabilityRequest& r, const JobControl& control) {
  FieldChecks checks;
  if (r.jobs && *r.jobs < 1)
    checks.problem("jobs", std::to_string(*r.jobs),
                   "expected a positive number of cases at once, found " + std::to_string(*r.jobs) +
                       "; leave it out for every core");
  checks.throw_if_any();
  StabilityResult result;
  result.dir = r.dir.empty() ? default_stability_dir() : r.dir;
  std::vector<std::string> files;
  std::error_code ec;
  if (!std::filesystem::is_directory(result.dir, ec))
    throw InputError(SourceLocation::of_field("dir", result.dir),
                     "expected a folder of scenes (scenes/extreme), found none there");
  for (const auto& entry : std::filesystem::directory_iterator(result.dir)) {
    if (entry.path().extension() == ".yaml" &&
        (r.only.empty() || entry.path().stem().string().find(r.only) != std::string::npos))
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw InputError(SourceLocation::of_field("only", r.only),
                     "no scene of " + result.dir + " has a name that holds this");
  const SceneInputs inputs = scene_inputs(asset_dir(r.assets));
  std::vector<Scene> scenes;
  for (const std::string& file : files)
    scenes.push_back(load_scene_file(file, {}, inputs.paper, inputs.parts));
  if (!r.out.empty()) prepare_output_folder(r.out, "out");

  // Cases are independent: share them among workers; asked to stop, they take no more.
  std::vector<std::optional<StabilityRow>> rows(scenes.size());
  std::atomic<std::size_t> next{0};
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(
      std::max(1u, r.jobs ? static_cast<unsigned>(*r.jobs) : std::thread::hardware_concurrency()),
      scenes.size()));
  std::atomic<unsigned> finished{0};
  {
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < workers; ++w) {
      pool.emplace_back([&] {
        for (std::size_t i = next++; i < scenes.size() && !control.stopping(); i = next++)
          rows[i] = run_stability_case(scenes[i]);
        ++finished;
      });
    }
    while (finished.load() < workers) {
      control.poll_stopping();
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    for (std::thread& worker : pool) worker.join();
  }
  for (std::optional<StabilityRow>& row : rows) {
    if (row)
      result.rows.push_back(std::move(*row));
    else
      ++result.not_run;
  }
  if (!r.out.empty()) {
    std::string csv =
        "case,expected,found,as_expected,largest_step_s,period_error,condition_period,wall_s\n";
    for (const StabilityRow& row : result.rows)
      csv += fmt::format("{},{},{},{},{},{},{},{}\n", row.name, regime_name(row.expected),
                         regime_name(row.found), row.as_expected ? 1 : 0,
                         row.largest_step ? fmt::format("{}", *row.largest_step) : "",
                         row.period_error ? fmt::format("{}", *row.period_error) : "",
                         row.condition_period, row.wall_s);
    const std::string csv_file = r.out + "/stability.csv";
    const std::string json_file = r.out + "/stability.json";
    write_file_atomic(csv_file, csv);
    write_file_atomic(json_file, result.json()["cases"].dump(2) + "\n");
    result.written = {csv_file, json_file};
  }
  return result;
}

}  // namespace fl
