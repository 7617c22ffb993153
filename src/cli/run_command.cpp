// frictionlab run SCENE: one simulation of a scene, summarised against the analytic model.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "cli/output_paths.hpp"
#include "cli/plot_script.hpp"
#include "cli/scene_options.hpp"
#include "cli/stop_signals.hpp"
#include "io/input_error.hpp"
#include "lab/experiment.hpp"
#include "lab/run_outputs.hpp"
#include "lab/step_choice.hpp"
#include "lab/video_recorder.hpp"
#include "scene/captions_yaml.hpp"
#include "scene/video_format.hpp"

namespace fl::cli {
namespace {

struct RunCommandOptions {
  SceneOptions scene;
  std::string out;
  std::string accuracy;
  bool json = false;
  bool plot = false;  // periods.png in --out
  // Frames of the run (--video, --frames, --still and their settings).
  VideoRequest video;
  std::string size;
  std::string slow_motion;
  std::string camera;
  std::string orbit;     // a rate, e.g. "10 deg/s"
  std::string captions;  // a captions file
};

void print_video(const VideoReport& v, const VideoRequest& request) {
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
  for (const auto& [label, path] :
       {std::pair{"video file", request.video}, std::pair{"frames", request.frames},
        std::pair{"still", request.still}}) {
    if (!path.empty()) fmt::print("  {:<22} {}\n", label, path);
  }
}

// An option the run would ignore is refused: the frame options without frames to draw, and a
// time step both set and picked.
void refuse_ignored_options(const RunCommandOptions& o) {
  if (!o.video.any()) {
    const std::pair<const char*, bool> frame_options[] = {
        {"--gl", !o.video.gl.empty()},          {"--size", !o.size.empty()},
        {"--fps", o.video.fps.has_value()},     {"--slow-motion", !o.slow_motion.empty()},
        {"--camera", !o.camera.empty()},        {"--orbit", !o.orbit.empty()},
        {"--title", o.video.title.has_value()}, {"--captions", !o.captions.empty()}};
    for (const auto& [name, given] : frame_options)
      if (given)
        throw InputError(SourceLocation{name, 0, 0},
                         "this option shapes the frames of --video, --frames or --still, and the "
                         "run draws none; add one of them, or drop it");
  }
  if (!o.accuracy.empty())
    for (const std::string& text : o.scene.overrides)
      if (parse_override(text).path == "world.time_step")
        throw InputError(SourceLocation{"--set " + text, 0, 0},
                         "--accuracy picks the time step, so this one would be ignored; give one "
                         "of them");
}

int run_run(const RunCommandOptions& o, const GlobalOptions& global) {
  refuse_ignored_options(o);
  // A video format it cannot write is refused before anything is loaded or created (a folder
  // given as the file is refused below, saying so).
  std::error_code folder_error;
  if (!o.video.video.empty() && !std::filesystem::is_directory(o.video.video, folder_error)) {
    const std::string problem = video_file_problem(o.video.video);
    if (!problem.empty()) throw InputError(SourceLocation{"--video", 0, 0}, problem);
  }
  // --orbit and --captions are read before the scene: a mistake in them costs no loading.
  VideoRequest request = o.video;
  if (!o.orbit.empty())
    request.orbit = option_quantity(o.orbit, Dimension::kAngularSpeed, "--orbit");
  if (!o.captions.empty()) request.captions = load_captions_file(o.captions);
  Scene scene = load_scene_with_options(o.scene, global);
  if (!o.accuracy.empty()) {
    const double target = option_quantity(o.accuracy, Dimension::kDimensionless, "--accuracy");
    scene.world.time_step = step_for_accuracy(scene, target);
    if (!o.json && scene.world.duration / scene.world.time_step <= 1e9)
      fmt::print("--accuracy {}: time step {:.4g} ms (predicted integrator bias {:.2e})\n",
                 o.accuracy, scene.world.time_step * 1e3, predicted_integrator_bias(scene));
  }
  // Checked before the run: a step the run can take, places to write, and a plot's needs.
  if (scene.world.duration / scene.world.time_step > 1e9)
    throw InputError(SourceLocation{"--accuracy " + o.accuracy, 0, 0},
                     fmt::format("expected a time step the run can take, found {:.3g} s: {:.3g} "
                                 "s of simulated time would take {:.3g} steps, more than 1e9; ask "
                                 "for a looser accuracy or a shorter --duration",
                                 scene.world.time_step, scene.world.duration,
                                 scene.world.duration / scene.world.time_step));
  if (!o.out.empty()) prepare_output_folder(o.out, "--out");
  if (!o.video.video.empty()) prepare_output_file(o.video.video, "--video");
  if (!o.video.still.empty()) prepare_output_file(o.video.still, "--still");
  if (!o.video.frames.empty()) prepare_output_folder(o.video.frames, "--frames");
  if (o.plot && o.out.empty())
    throw InputError(SourceLocation{"--plot", 0, 0},
                     "expected --out DIR as well: the plot is drawn from DIR/periods.csv; add "
                     "--out DIR");
  if (o.plot && (!scene.sensor || scene.magnets.empty() || !scene.output.hall ||
                 !scene.output.periods || !scene.output.summary))
    throw InputError(SourceLocation{"--plot", 0, 0},
                     "expected a scene with a Hall sensor, magnets and output.hall, "
                     "output.periods and output.summary on, found a scene without them: there are "
                     "no periods to plot; drop --plot");
  RunOptions options;
  options.record_trajectory = !o.out.empty() && scene.output.trajectory;
  options.record_hall = !o.out.empty() && scene.output.hall;
  // A run that asks for no frames makes no recorder: no GL context, no mesh, no encoder.
  std::unique_ptr<VideoRecorder> recorder;
  if (o.video.any()) {
    request.asset_dir = resolve_asset_dir(global.asset_dir);
    if (!o.size.empty()) {
      request.size = parse_video_size(o.size);
      if (!request.size)
        throw InputError(
            SourceLocation{"--size", 0, 0},
            "expected WIDTHxHEIGHT in pixels (e.g. 1280x720), found \"" + o.size + "\"");
    }
    if (!o.slow_motion.empty())
      request.slow_motion =
          option_quantity(o.slow_motion, Dimension::kDimensionless, "--slow-motion");
    if (!o.camera.empty()) request.camera = o.camera;
    try {
      recorder = std::make_unique<VideoRecorder>(scene, request);
    } catch (const VideoUnavailable& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 2;
    }
    if (const std::string note = recorder->note(); !note.empty())
      fmt::print(stderr, "note: {}\n", note);
    options.observer = [&recorder](const StepView& view) { recorder->observe(view); };
  }
  options.record_cycles = !o.out.empty() && scene.output.cycles;
  // Ctrl-C or SIGTERM ends the run after its step; what it did is kept, closed and reported.
  options.stop = &stop_requested();
  // A run longer than a few seconds on a terminal says how far it is.
  const bool tty = isatty(2) == 1 && !o.json;
  const auto wall_start = std::chrono::steady_clock::now();
  double shown = 0.0;
  if (tty)
    options.progress = [&](double t) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      if (wall < 3.0 || wall - shown < 0.25) return;
      shown = wall;
      fmt::print(stderr, "\r\033[Krun: t = {:.1f} of {:.1f} s ({:.0f} %)", t, scene.world.duration,
                 100.0 * t / scene.world.duration);
    };
  RunRecording recording;
  const CompiledRig rig = compile_rig(scene);
  RunSummary summary;
  std::optional<VideoReport> video;
  {
    StopSignals signals;
    summary = run_experiment(rig, options, &recording);
    if (shown > 0.0) fmt::print(stderr, "\r\033[K");
    // The video up to its last frame, playable, even when the run was interrupted.
    if (recorder)
      video = recorder->finish(VideoEnding{summary.failure.value_or(""), summary.duration});
  }
  if (!o.out.empty()) write_run_outputs(o.out, rig, summary, recording);
  if (o.json) {
    nlohmann::json j = summary_json(summary);
    j.update(timing_json(summary));
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}", summary_text(summary));
    if (!o.out.empty()) fmt::print("  outputs                {}/\n", o.out);
    if (video) print_video(*video, o.video);
  }
  // The plot last, after the results it draws are printed and written: its failure loses none.
  if (o.plot) {
    const std::string plot = o.out + "/periods.png";
    try {
      run_plot_script("plot_periods.py", {o.out, plot});
    } catch (const std::runtime_error& e) {
      fmt::print(stderr, "error: no plot: {}; the results above and in {}/ are complete\n",
                 e.what(), o.out);
      return 1;
    }
    if (!o.json) fmt::print("  plot                   {}\n", plot);
  }
  if (summary.interrupted_at) {
    fmt::print(stderr,
               "frictionlab run: interrupted at t = {:.3f} s; kept: the summary above{}{} (each "
               "marked with interrupted_at_s)\n",
               *summary.interrupted_at, o.out.empty() ? "" : ", the outputs in " + o.out + "/",
               video ? ", the video up to its last frame" : "");
    return stop_exit_status();
  }
  // A guard stopped the run: the outputs up to that point are written, and the status says so.
  return summary.failure || summary.regime == Regime::kNumericallyFailed ? 3 : 0;
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
  sub->add_flag("--plot", options->plot,
                "With --out: draw the estimator's periods over the run as DIR/periods.png "
                "(python3 + matplotlib)");
  sub->add_option(
      "--video", options->video.video,
      "Write a video of the rig with the Hall trace and the estimate: FILE.mp4 (H.264), "
      "FILE.gif (animated GIF) or FILE.webm (VP9)");
  sub->add_option("--frames", options->video.frames,
                  "Write every frame as DIR/frame_000000.png, ... (earlier frames are replaced)");
  sub->add_option("--still", options->video.still, "Write the frame at the run's end as a PNG");
  sub->add_option("--gl", options->video.gl,
                  "GL back end: osmesa, egl or auto (default: $FRICTIONLAB_GL, then auto)");
  sub->add_option("--size", options->size,
                  "Frame size WIDTHxHEIGHT (default: the scene's, 1280x720)");
  sub->add_option("--fps", options->video.fps, "Frames per second of video (default 30)");
  sub->add_option("--slow-motion", options->slow_motion,
                  "Slow-motion factor: 4 renders 4 x fps frames per simulated second (default 1)");
  sub->add_option("--camera", options->camera, "Camera preset: front, top or sensor");
  sub->add_option("--orbit", options->orbit,
                  "Turn the camera about the rig at this rate of video time, e.g. \"10 deg/s\" "
                  "(default: the scene's, 0)");
  sub->add_option("--title", options->video.title,
                  "The title card's title; turns the title card on");
  sub->add_option("--captions", options->captions,
                  "Captions from FILE (a YAML map with a `captions:` list, as the scene's "
                  "video.captions), replacing the scene's");
  return Command{sub, [options, &global] { return run_run(*options, global); }};
}

}  // namespace fl::cli
