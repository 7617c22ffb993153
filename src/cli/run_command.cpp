// frictionlab run SCENE: one simulation of a scene, summarised against the analytic model.
#include <unistd.h>

#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/field_spelling.hpp"
#include "cli/scene_options.hpp"
#include "cli/stop_signals.hpp"
#include "lab/request/run_request.hpp"
#include "lab/run/run_outputs.hpp"

namespace fl::cli {
namespace {

struct RunCommandOptions {
  SceneOptions scene;
  RunRequest request;
  std::string accuracy;
  bool json = false;
  std::string size;
  std::string slow_motion;
  std::string camera;
  std::string orbit;  // a rate, e.g. "10 deg/s"
  std::optional<std::string> title;
};

void print_video(const VideoReport& v, const RunRequest& request) {
  fmt::print(
      "  video                  {} frames ({} title, {} ending), {}x{} at {} fps, slow motion "
      "x{:g}, "
      "camera {}\n",
      v.frames, v.title_frames, v.ending_frames, v.width, v.height, v.fps, v.slow_motion, v.camera);
  fmt::print(
      "  rendering              {:.2f} s drawing, {:.2f} s set-up, {:.2f} s to finish; "
      "{} triangles a frame (LEGO frame {} of {})\n",
      v.render_seconds, v.setup_seconds, v.finish_seconds, v.triangles, v.frame_triangles,
      v.frame_triangles_full);
  fmt::print("  renderer               {}\n", v.backend);
  for (const auto& [label, path] :
       {std::pair{"video file", request.video}, std::pair{"frames", request.frames},
        std::pair{"still", request.still}}) {
    if (!path.empty()) fmt::print("  {:<22} {}\n", label, path);
  }
}

// The options' texts as the request's fields: only what was given.
RunRequest request_of(const RunCommandOptions& o, const GlobalOptions& global) {
  RunRequest r = o.request;
  r.scene = scene_source_of(o.scene, global);
  r.set = o.scene.overrides;
  if (!o.scene.duration.empty()) r.duration = o.scene.duration;
  if (!o.accuracy.empty()) r.accuracy = o.accuracy;
  if (!o.size.empty()) r.size = o.size;
  if (!o.slow_motion.empty()) r.slow_motion = o.slow_motion;
  if (!o.camera.empty()) r.camera = o.camera;
  if (!o.orbit.empty()) r.orbit = o.orbit;
  r.title = o.title;
  return r;
}

int run_run(const RunCommandOptions& o, const GlobalOptions& global) {
  const PreparedRun prepared = prepare_run(request_of(o, global));
  for (const std::string& warning : prepared.warnings)
    fmt::print(stderr, "warning: {}\n", spelled(warning));
  const double duration = prepared.rig->world.duration;
  if (prepared.chosen_time_step && !o.json)
    fmt::print("--accuracy {}: time step {:.4g} ms, sized by the {}\n", o.accuracy,
               *prepared.chosen_time_step * 1e3, prepared.chosen_step_why);
  RunControl control;
  // Ctrl-C or SIGTERM ends the run after its step; what it did is kept, closed and reported.
  control.stop = &stop_requested();
  control.note = [](const std::string& note) { fmt::print(stderr, "note: {}\n", spelled(note)); };
  // A run longer than a few seconds on a terminal says how far it is.
  const bool tty = isatty(2) == 1 && !o.json;
  const auto wall_start = std::chrono::steady_clock::now();
  double shown = 0.0;
  if (tty)
    control.progress = [&](double t) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      if (wall < 3.0 || wall - shown < 0.25) return;
      shown = wall;
      fmt::print(stderr, "\r\033[Krun: t = {:.1f} of {:.1f} s ({:.0f} %)", t, duration,
                 100.0 * t / duration);
    };
  RunResult result;
  {
    StopSignals signals;
    result = execute_run(prepared, control);
    if (shown > 0.0) fmt::print(stderr, "\r\033[K");
  }
  const RunSummary& summary = result.summary;
  if (o.json) {
    nlohmann::json j = summary_json(summary);
    j.update(timing_json(summary));
    if (result.video) j["renderer"] = result.video->backend;
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}", spelled(summary_text(summary)));
    if (!result.out.empty()) fmt::print("  outputs                {}/\n", result.out);
    if (result.video) print_video(*result.video, o.request);
    if (!result.plot.empty()) fmt::print("  plot                   {}\n", result.plot);
  }
  if (!result.plot_failure.empty())
    fmt::print(stderr, "error: no plot: {}; the results above and in {}/ are complete\n",
               result.plot_failure, result.out);
  if (summary.interrupted_at) {
    fmt::print(stderr,
               "frictionlab run: interrupted at t = {:.3f} s; kept: the summary above{}{} (each "
               "marked with interrupted_at_s)\n",
               *summary.interrupted_at,
               result.out.empty() ? "" : ", the outputs in " + result.out + "/",
               result.video ? ", the video up to its last frame" : "");
    return stop_exit_status();
  }
  // A guard stopped the run: the outputs up to that point are written, and the status says so.
  return exit_status(result.outcome());
}

}  // namespace

Command add_run_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene and compare its period with theory");
  add_scene_options(*sub, options->scene);
  sub->add_option("--out", options->request.out,
                  "Folder for summary.json, timing.json, trajectory.csv and hall.csv");
  sub->add_option(
      "--accuracy", options->accuracy,
      "Pick the largest time step whose predicted period bias is below this, e.g. 0.01%");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the summary");
  sub->add_flag("--plot", options->request.plot,
                "With --out: draw the estimator's periods over the run as DIR/periods.png "
                "(python3 + matplotlib)");
  sub->add_option(
      "--video", options->request.video,
      "Write a video of the rig with the Hall trace and the estimate: FILE.mp4 (H.264), "
      "FILE.gif (animated GIF) or FILE.webm (VP9)");
  sub->add_option("--frames", options->request.frames,
                  "Write every frame as DIR/frame_000000.png, ... (earlier frames are replaced)");
  sub->add_option("--still", options->request.still, "Write the frame at the run's end as a PNG");
  sub->add_option("--gl", options->request.gl,
                  "GL back end: osmesa, egl or auto (default: $FRICTIONLAB_GL, then auto)");
  sub->add_option("--size", options->size,
                  "Frame size WIDTHxHEIGHT (default: the scene's, 1280x720)");
  sub->add_option("--fps", options->request.fps, "Frames per second of video (default 30)");
  sub->add_option("--slow-motion", options->slow_motion,
                  "Slow-motion factor: 4 renders 4 x fps frames per simulated second (default 1)");
  sub->add_option(
      "--camera", options->camera,
      "Camera preset: front, top, sensor or phone (a phone's plain recording beside the rig)");
  sub->add_option("--orbit", options->orbit,
                  "Turn the camera about the rig at this rate of video time, e.g. \"10 deg/s\" "
                  "(default: the scene's, 0)");
  sub->add_option("--title", options->title, "The title card's title; turns the title card on");
  sub->add_option("--captions", options->request.captions,
                  "Captions from FILE (a YAML map with a `captions:` list, as the scene's "
                  "video.captions), replacing the scene's");
  return Command{sub, [options, &global] { return run_run(*options, global); }};
}

}  // namespace fl::cli
