// frictionlab run SCENE: one simulation of a scene, summarised against the analytic model.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "cli/scene_options.hpp"
#include "lab/experiment.hpp"
#include "lab/run_outputs.hpp"
#include "lab/step_choice.hpp"

namespace fl::cli {
namespace {

struct RunCommandOptions {
  SceneOptions scene;
  std::string out;
  std::string accuracy;
  bool json = false;
};

int run_run(const RunCommandOptions& o, const GlobalOptions& global) {
  Scene scene = load_scene_with_options(o.scene, global);
  if (!o.accuracy.empty()) {
    const double target = option_quantity(o.accuracy, Dimension::kDimensionless, "--accuracy");
    scene.world.time_step = step_for_accuracy(scene, target);
    if (!o.json)
      fmt::print("--accuracy {}: time step {:.4g} ms (predicted integrator bias {:.2e})\n",
                 o.accuracy, scene.world.time_step * 1e3, predicted_integrator_bias(scene));
  }
  RunOptions options;
  options.record_trajectory = !o.out.empty() && scene.output.trajectory;
  options.record_hall = !o.out.empty() && scene.output.hall;
  RunRecording recording;
  const RunSummary summary = run_experiment(scene, options, &recording);
  if (!o.out.empty()) write_run_outputs(o.out, scene, summary, recording);
  if (o.json) {
    nlohmann::json j = summary_json(summary);
    j.update(timing_json(summary));
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}", summary_text(summary));
    if (!o.out.empty()) fmt::print("  outputs                {}/\n", o.out);
  }
  // A guard stopped the run: the outputs up to that point are written, and the status says so.
  return summary.failure ? 3 : 0;
}

}  // namespace

Command add_run_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene and compare its period with theory");
  add_scene_options(*sub, options->scene);
  sub->add_option("--out", options->out,
                  "Folder for summary.json, timing.json, trajectory.csv and hall.csv");
  sub->add_option(
      "--accuracy", options->accuracy,
      "Pick the largest time step whose predicted period bias is below this, e.g. 0.01%");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the summary");
  return Command{sub, [options, &global] { return run_run(*options, global); }};
}

}  // namespace fl::cli
