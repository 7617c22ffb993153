// frictionlab accuracy SCENE: the work-precision study, period error against run time.
#include <string>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/plot_failure.hpp"
#include "cli/scene_options.hpp"
#include "cli/stop_signals.hpp"
#include "lab/request/study_requests.hpp"

namespace fl::cli {
namespace {

struct AccuracyOptions {
  SceneOptions scene;
  std::string out = AccuracyRequest{}.out;
  bool plot = false;
  bool json = false;
  int periods = AccuracyRequest{}.periods;
};

int run_accuracy(const AccuracyOptions& o, const GlobalOptions& global) {
  AccuracyRequest request;
  request.scene = scene_source_of(o.scene, global);
  request.set = o.scene.overrides;
  if (!o.scene.duration.empty()) request.duration = o.scene.duration;
  request.periods = o.periods;
  request.out = o.out;
  request.plot = o.plot;
  const StopSignals signals;
  const AccuracyResult result = study_accuracy(request, JobControl{&stop_requested(), {}});
  const AccuracyStudy& study = result.study;
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    if (study.interrupted) return stop_exit_status();
    return plot_failure_status(result.plot_failure);
  }
  fmt::print("frictionlab accuracy: {} (thick-plate T = {:.6f} s, {} periods per point)\n",
             result.scene, study.period_thick, result.periods);
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
  std::string written;
  for (const std::string& w : result.written) written += (written.empty() ? "" : ", ") + w;
  fmt::print("  written: {}\n", written);
  if (study.interrupted) {
    fmt::print(stderr,
               "frictionlab accuracy: interrupted after {} points; kept: those points above and "
               "in {}\n",
               study.points.size(), written);
    return stop_exit_status();
  }
  return plot_failure_status(result.plot_failure);
}

}  // namespace

Command add_accuracy_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<AccuracyOptions>();
  CLI::App* sub = app.add_subcommand(
      "accuracy", "Work-precision study: period error and amplitude drift against run time");
  add_scene_options(*sub, options->scene);
  sub->add_option("--out", options->out, "Folder for accuracy.csv/.json/.png")
      ->capture_default_str();
  sub->add_option("--periods", options->periods, "Periods simulated per point (3 to 1000)")
      ->capture_default_str();
  sub->add_flag("--plot", options->plot, "Draw accuracy.png (python3-matplotlib)");
  sub->add_flag("--json", options->json, "Print the fitted law as JSON");
  return Command{sub, [options, &global] { return run_accuracy(*options, global); }};
}

}  // namespace fl::cli
