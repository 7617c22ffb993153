// frictionlab accuracy SCENE: the work-precision study, period error against run time.
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "lab/studies/accuracy_study.hpp"

namespace fl::cli {
namespace {

struct AccuracyOptions {
  SceneOptions scene;
  std::string out = "out/accuracy";
  bool plot = false;
  bool json = false;
  int periods = 10;
};

std::string study_csv(const AccuracyStudy& study) {
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

int run_accuracy(const AccuracyOptions& o, const GlobalOptions& global) {
  // The study sets each point's length (--periods), step and solver iterations itself.
  if (!o.scene.duration.empty())
    throw InputError(SourceLocation{"--duration", 0, 0},
                     "each point simulates --periods periods of the thick-plate period; give "
                     "--periods N instead");
  for (const std::string& text : o.scene.overrides) {
    const std::string path = parse_override(text).path;
    if (path == "world.duration" || path == "world.time_step" || path == "world.solver_iterations")
      throw InputError(SourceLocation{"--set " + text, 0, 0},
                       "the study sets " + path +
                           " for each point of its grid, so this would be ignored; drop it (the "
                           "length is --periods)");
  }
  const Scene scene = load_scene_with_options(o.scene, global);
  AccuracyGrid grid;
  grid.periods = o.periods;
  prepare_output_folder(o.out, "out");
  const AccuracyStudy study = run_accuracy_study(scene, grid);
  nlohmann::json j{{"scene", scene.name},
                   {"period_thick_s", study.period_thick},
                   {"omega_rad_s", study.omega},
                   {"csv", o.out + "/accuracy.csv"}};
  if (study.law) {
    j["law"] = {{"coefficient", study.law->coefficient},
                {"exponent", study.law->exponent},
                {"points", study.law->points},
                {"theory_coefficient", 1.0 / 24.0},
                {"theory_exponent", 2.0}};
  }
  write_file_atomic(o.out + "/accuracy.csv", study_csv(study));
  write_file_atomic(o.out + "/accuracy.json", j.dump(2) + "\n");
  if (o.plot) {
    run_plot_script("plot_accuracy.py",
                    {o.out + "/accuracy.csv", o.out + "/accuracy.json", o.out + "/accuracy.png"});
  }
  if (o.json) {
    fmt::print("{}\n", j.dump(2));
    return 0;
  }
  fmt::print("frictionlab accuracy: {} (thick-plate T = {:.6f} s, {} periods per point)\n",
             scene.name, study.period_thick, grid.periods);
  fmt::print("  {:>10} {:>5} {:>13} {:>13} {:>13} {:>14}\n", "dt [ms]", "iter", "period error",
             "predicted", "drift/period", "wall/sim s [ms]");
  for (const AccuracyPoint& p : study.points) {
    fmt::print("  {:>10.4f} {:>5} {:>13} {:>13.3e} {:>13} {:>14.3f}\n", p.time_step * 1e3,
               p.solver_iterations, p.valid ? fmt::format("{:.3e}", p.period_error) : "no period",
               p.predicted_error, p.valid ? fmt::format("{:.2e}", p.amplitude_drift) : "-",
               p.wall_per_simulated_second * 1e3);
  }
  if (study.law)
    fmt::print(
        "  fitted law: error = -{:.4f} (omega dt)^{:.3f} over {} points (theory: -(omega dt)^2/24, "
        "1/24 = {:.4f})\n",
        study.law->coefficient, study.law->exponent, study.law->points, 1.0 / 24.0);
  fmt::print("  written: {}/accuracy.csv, accuracy.json{}\n", o.out,
             o.plot ? ", accuracy.png" : "");
  return 0;
}

}  // namespace

Command add_accuracy_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<AccuracyOptions>();
  CLI::App* sub = app.add_subcommand(
      "accuracy", "Work-precision study: period error and amplitude drift against run time");
  add_scene_options(*sub, options->scene);
  sub->add_option("--out", options->out, "Folder for accuracy.csv/.json/.png")
      ->capture_default_str();
  sub->add_option("--periods", options->periods, "Periods simulated per point")
      ->capture_default_str()
      ->check(CLI::Range(3, 1000));
  sub->add_flag("--plot", options->plot, "Draw accuracy.png (python3-matplotlib)");
  sub->add_flag("--json", options->json, "Print the fitted law as JSON");
  return Command{sub, [options, &global] { return run_accuracy(*options, global); }};
}

}  // namespace fl::cli
