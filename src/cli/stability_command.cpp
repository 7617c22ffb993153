// frictionlab stability: the catalogue of stiff and extreme cases, each diagnosed against theory.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "cli/scene_options.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/studies/stability_study.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::cli {
namespace {

struct StabilityOptions {
  std::string dir = std::string(FRICTIONLAB_DEFAULT_SOURCE_DIR) + "/scenes/extreme";
  std::string out;
  std::string only;
  int jobs = 0;
  bool json = false;
};

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

int run_stability(const StabilityOptions& o, const GlobalOptions& global) {
  std::vector<std::string> files;
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec))
    throw InputError({o.dir, 0, 0}, "not a folder of scenes (expected scenes/extreme)");
  for (const auto& entry : std::filesystem::directory_iterator(o.dir)) {
    if (entry.path().extension() == ".yaml" &&
        (o.only.empty() || entry.path().stem().string().find(o.only) != std::string::npos))
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError({o.dir, 0, 0}, "no scene matches");
  const SceneInputs sources = scene_sources(global);
  std::vector<Scene> scenes;
  for (const std::string& file : files)
    scenes.push_back(load_scene_file(file, {}, sources.paper, sources.parts));

  if (!o.out.empty()) prepare_output_folder(o.out, "out");
  // Cases are independent: share them among workers.
  std::vector<StabilityRow> rows(scenes.size());
  std::atomic<std::size_t> next{0};
  const unsigned workers = std::max(
      1u, o.jobs > 0 ? static_cast<unsigned>(o.jobs) : std::thread::hardware_concurrency());
  {
    std::vector<std::jthread> pool;
    for (unsigned w = 0; w < std::min<std::size_t>(workers, scenes.size()); ++w) {
      pool.emplace_back([&] {
        for (std::size_t i = next++; i < scenes.size(); i = next++)
          rows[i] = run_stability_case(scenes[i]);
      });
    }
  }

  nlohmann::json all = nlohmann::json::array();
  int unexpected = 0;
  for (const StabilityRow& r : rows) {
    all.push_back(row_json(r));
    if (!r.as_expected) ++unexpected;
  }
  if (!o.out.empty()) {
    std::string csv =
        "case,expected,found,as_expected,largest_step_s,period_error,condition_period,wall_s\n";
    for (const StabilityRow& r : rows)
      csv += fmt::format(
          "{},{},{},{},{},{},{},{}\n", r.name, regime_name(r.expected), regime_name(r.found),
          r.as_expected ? 1 : 0, r.largest_step ? fmt::format("{}", *r.largest_step) : "",
          r.period_error ? fmt::format("{}", *r.period_error) : "", r.condition_period, r.wall_s);
    write_file_atomic(o.out + "/stability.csv", csv);
    write_file_atomic(o.out + "/stability.json", all.dump(2) + "\n");
  }
  if (o.json) {
    fmt::print("{}\n", nlohmann::json{{"cases", all}, {"unexpected", unexpected}}.dump(2));
    return unexpected == 0 ? 0 : 1;
  }
  fmt::print("frictionlab stability: {} cases from {}\n\n", rows.size(), o.dir);
  fmt::print(
      "| case | parameters | theory expects | found | largest trustworthy step | period error at "
      "the "
      "scene's step | d ln mu / d ln T, d ln h_c | run time |\n");
  fmt::print("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const StabilityRow& r : rows) {
    fmt::print(
        "| {} | {} | {} | {}{} | {} | {} | {} | {:.2f} s |\n", r.name, r.parameters,
        regime_name(r.expected), regime_name(r.found), r.as_expected ? "" : " (UNEXPECTED)",
        r.largest_step ? fmt::format("{:.3g} ms", *r.largest_step * 1e3) : "none: " + r.step_note,
        r.period_error ? fmt::format("{:+.2e}", *r.period_error) : "-",
        r.condition_period > 0 ? fmt::format("{:.3f}, {:.3f}", r.condition_period, r.condition_h_c)
                               : std::string("-"),
        r.wall_s);
  }
  fmt::print("\n{} of {} cases end in the regime theory expects.\n", rows.size() - unexpected,
             rows.size());
  for (const StabilityRow& r : rows) {
    if (!r.as_expected)
      fmt::print("  {}: expected {} ({}), found {}: {}\n", r.name, regime_name(r.expected),
                 r.expected_reason, regime_name(r.found), r.evidence);
  }
  return unexpected == 0 ? 0 : 1;
}

}  // namespace

Command add_stability_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<StabilityOptions>();
  CLI::App* sub = app.add_subcommand(
      "stability",
      "Run the catalogue of stiff and extreme cases and check each regime against theory");
  sub->add_option("--dir", options->dir, "Folder of the catalogue's scenes")->capture_default_str();
  sub->add_option("--only", options->only, "Only the cases whose name contains this");
  sub->add_option("-j,--jobs", options->jobs, "Cases run at once (default: all cores)");
  sub->add_option("--out", options->out, "Folder for stability.csv and stability.json");
  sub->add_flag("--json", options->json, "Print the table as JSON");
  return Command{sub, [options, &global] { return run_stability(*options, global); }};
}

}  // namespace fl::cli
