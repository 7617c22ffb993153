#include "lab/request/run_request.hpp"
#include "lab/video/caption_values.hpp"

#include <cctype>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/integrator_error.hpp"
#include "io/field_ref.hpp"
#include "lab/recorder/video_recorder.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "lab/run/phone_csv.hpp"
#include "lab/run/run_files.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab/run/step_choice.hpp"
#include "scene/captions_yaml.hpp"
#include "scene/compiled_rig.hpp"
#include "scene/video_format.hpp"

namespace fl {
namespace {

// The most steps a run may take: a step so small that the run would never end is refused.
constexpr double kMostSteps = 1e9;

// The fields that shape frames, and whether the request gives each.
std::vector<std::pair<const char*, bool>> frame_fields(const RunRequest& r) {
  return {{"gl", !r.gl.empty()},
          {"size", r.size.has_value()},
          {"fps", r.fps.has_value()},
          {"slow_motion", r.slow_motion.has_value()},
          {"camera", r.camera.has_value()},
          {"orbit", r.orbit.has_value()},
          {"title", r.title.has_value()},
          {"captions", !r.captions.empty()}};
}

// The frames' request from the fields; problems by field.
VideoRequest frames_request(const RunRequest& r, FieldChecks& checks) {
  VideoRequest v;
  v.video = r.video;
  v.frames = r.frames;
  v.still = r.still;
  v.gl = r.gl;
  if (r.size) {
    if (const std::string* text = std::get_if<std::string>(&*r.size)) {
      v.size = parse_video_size(*text);
      if (!v.size)
        checks.problem("size",
                       "expected WIDTHxHEIGHT in pixels (e.g. 1280x720), found \"" + *text + "\"");
    } else {
      v.size = std::get<std::array<int, 2>>(*r.size);
    }
  }
  v.fps = r.fps;
  if (r.slow_motion)
    v.slow_motion = checks.quantity(*r.slow_motion, Dimension::kDimensionless, "slow_motion");
  v.camera = r.camera;
  v.title = r.title;
  if (r.orbit) v.orbit = checks.quantity(*r.orbit, Dimension::kAngularSpeed, "orbit");
  return v;
}

// The files a run draws frames into, checked by name before anything is loaded or created.
void check_frame_files(const RunRequest& r, FieldChecks& checks) {
  // A video format it cannot write is refused before anything is loaded or created (a folder
  // given as the file is refused below, saying so).
  std::error_code folder_error;
  if (!r.video.empty() && !std::filesystem::is_directory(r.video, folder_error)) {
    const std::string problem = video_file_problem(r.video);
    if (!problem.empty()) checks.problem("video", problem);
  }
  // The still is a PNG: a name that says otherwise (x.jpg) would be a file its viewer misreads.
  if (!r.still.empty() && !std::filesystem::is_directory(r.still, folder_error)) {
    std::string extension = std::filesystem::path(r.still).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png")
      checks.problem("still",
                     "expected a .png file (the still is a PNG image), found " +
                         (extension.empty() ? std::string("a name without an extension")
                                            : "\"" + extension + "\"") +
                         "; name it " +
                         std::filesystem::path(r.still).replace_extension(".png").string());
  }
}

// The places the run writes, made ready before it runs: none may replace the scene or the
// captions read, and the folder must hold the run's files.
void make_output_places(const RunRequest& r, const Scene& scene, const CompiledRig& rig,
                        FieldChecks& checks) {
  // Outputs that would replace the scene or the captions read are refused before any is made.
  const std::vector<InputFile> inputs = {{r.scene.file, "the scene"},
                                         {r.captions, "the captions file"}};
  std::vector<std::string> written = {"summary.json", "timing.json", "trajectory.csv",
                                      "hall.csv",     "periods.csv", "cycles.csv",
                                      "jumps.csv",    "periods.png"};
  for (std::size_t i = 0; i < rig.phones.size(); ++i) written.push_back(phone_csv_name(rig, i));
  refuse_overwriting_inputs(r.out, written, "out", inputs);
  refuse_overwriting_inputs(r.video, "video", inputs);
  refuse_overwriting_inputs(r.still, "still", inputs);
  if (!r.out.empty()) {
    prepare_output_folder(r.out, "out");
    // The files stream to the disk as the run goes: a run they would not fit is refused now, not
    // after minutes of simulation.
    const double needed = run_files_bytes_at_most(scene.output, rig);
    std::error_code ec;
    const std::filesystem::space_info space = std::filesystem::space(r.out, ec);
    if (!ec && static_cast<double>(space.available) < needed) {
      const auto size = [](double bytes) {
        return bytes >= 1e9 ? fmt::format("{:.3g} GB", bytes / 1e9)
                            : fmt::format("{:.3g} MB", bytes / 1e6);
      };
      checks.problem(
          "out", r.out,
          fmt::format("expected a folder with room for the run's files, up to {} for "
                      "{:.4g} s of steps and samples, found {} free there; free some, "
                      "write elsewhere, shorten the {} or leave out output.trajectory",
                      size(needed), rig.world.duration, size(static_cast<double>(space.available)),
                      field_ref("duration")));
      checks.throw_if_any();
    }
  }
  if (!r.video.empty()) prepare_output_file(r.video, "video");
  if (!r.still.empty()) prepare_output_file(r.still, "still");
  if (!r.frames.empty()) prepare_output_folder(r.frames, "frames");
}

}  // namespace

PreparedRun prepare_run(const RunRequest& r) {
  FieldChecks checks;
  // An option the run would ignore is refused: what shapes frames without frames to draw, and a
  // time step both set and picked.
  if (!r.draws_frames()) {
    for (const auto& [field, given] : frame_fields(r))
      if (given)
        checks.problem(field, "this shapes the frames of " + field_ref("video") + ", " +
                                  field_ref("frames") + " or " + field_ref("still") +
                                  ", and the run draws none; add one of them, or drop it");
  }
  std::vector<SceneOverride> overrides = read_overrides(r.set, checks);
  if (r.accuracy) {
    std::vector<SceneOverride> all = r.scene.overrides;
    all.insert(all.end(), overrides.begin(), overrides.end());
    for (const SceneOverride& o : all)
      if (o.path == "world.time_step")
        checks.problem("accuracy", quantity_input_text(*r.accuracy),
                       "this picks the time step, so " +
                           field_ref("set", "world.time_step=" + o.value) +
                           " would be ignored; give one of them");
  }
  check_frame_files(r, checks);
  VideoRequest frames;
  if (r.draws_frames()) frames = frames_request(r, checks);
  const std::vector<SceneOverride> length = run_length_overrides(r.duration, r.seed, checks);
  overrides.insert(overrides.end(), length.begin(), length.end());
  std::optional<double> target;
  if (r.accuracy) {
    target = checks.quantity(*r.accuracy, Dimension::kDimensionless, "accuracy");
    // What the accuracy rule can honour (core/integrator_error.hpp), as a sweep's accuracy.
    if (!checks.has("accuracy") && !(*target > 0.0 && *target <= kLoosestPeriodAccuracy))
      checks.problem("accuracy", quantity_input_text(*r.accuracy),
                     fmt::format("expected a period accuracy above 0 and at most {:g} % (e.g. "
                                 "0.01%), found {}: a looser one would size a step of a quarter "
                                 "of the period or more, which resolves no oscillation",
                                 100.0 * kLoosestPeriodAccuracy, quantity_input_text(*r.accuracy)));
  }
  checks.throw_if_any();
  // The captions file, then the scene: a mistake in either is located in its file.
  if (!r.captions.empty()) frames.captions = load_captions_file(r.captions);

  PreparedRun out;
  SceneSource source = r.scene;
  source.overrides.insert(source.overrides.end(), overrides.begin(), overrides.end());
  const LoadedScene loaded = load_scene_source(std::move(source));
  const Scene& scene = *loaded.scene;
  out.scene = loaded.scene;
  out.output = scene.output;
  // The rig, compiled once for the whole run: the step the accuracy picks changes only the step
  // and the bias that follows from it.
  CompiledRig rig = compile_rig(scene);
  if (target) {
    try {
      const StepChoice choice = step_for_accuracy(rig, *target);
      rig = with_time_step(std::move(rig), choice.time_step);
      out.chosen_step_why = step_basis_name(choice.basis) + ": " + choice.reason;
    } catch (const DomainError& e) {
      checks.problem("accuracy", quantity_input_text(*r.accuracy), e.what());
      checks.throw_if_any();
    }
    out.chosen_time_step = rig.world.time_step;
    out.chosen_bias = rig.integrator_bias;
  }
  // A step the run can take, places to write, and a plot's needs, before the run.
  const WorldDesc& world = rig.world;
  if (world.duration / world.time_step > kMostSteps)
    checks.problem("accuracy", r.accuracy ? quantity_input_text(*r.accuracy) : std::string(),
                   fmt::format("expected a time step the run can take, found {:.3g} s: {:.3g} s "
                               "of simulated time would take {:.3g} steps, more than 1e9; ask "
                               "for a looser accuracy or a shorter {}",
                               world.time_step, world.duration, world.duration / world.time_step,
                               field_ref("duration")));
  if (r.plot && r.out.empty())
    checks.problem("plot", "expected " + field_ref("out") +
                               " as well: the plot is drawn from its periods.csv; add it");
  if (r.plot && (!rig.sensor || rig.magnets.empty() || !scene.output.hall ||
                 !scene.output.periods || !scene.output.summary))
    checks.problem("plot",
                   "expected a scene with a Hall sensor, magnets and output.hall, "
                   "output.periods and output.summary on, found a scene without them: there are "
                   "no periods to plot; drop " +
                       field_ref("plot"));
  checks.throw_if_any();
  make_output_places(r, scene, rig, checks);
  std::vector<std::string> caption_warnings;
  if (r.draws_frames()) {
    out.video = effective_video(scene, frames);  // the settings against the scene's, by field
    // Narration that cannot lie: the run's own values in, and what contradicts them said.
    const PaperTable& table = paper_table_in(asset_dir(loaded.source.asset_dir));
    out.video.captions = filled_captions(std::move(out.video.captions), rig, table);
    caption_warnings = caption_contradictions(out.video.captions, rig, table);
    frames.asset_dir = asset_dir(loaded.source.asset_dir);
    out.frames = std::move(frames);
  }
  out.rig = std::make_shared<const CompiledRig>(std::move(rig));
  out.out = r.out;
  out.plot = r.plot;
  out.record = r.record;
  out.warnings = checks.warnings();
  out.warnings.insert(out.warnings.end(), caption_warnings.begin(), caption_warnings.end());
  return out;
}

Outcome RunResult::outcome() const {
  if (summary.interrupted_at) return Outcome::kInterrupted;
  if (summary.failed()) return Outcome::kFailed;
  if (!plot_failure.empty()) return Outcome::kIncomplete;
  return Outcome::kDone;
}

RunResult execute_run(const PreparedRun& run, const RunControl& control) {
  // `record` keeps everything; `out` what its files need.
  RunOptions options;
  if (run.record)
    options.record_trajectory = options.record_hall = options.record_cycles =
        options.record_phones = true;
  else if (!run.out.empty())
    options = recording_for(run.output);
  // A run that asks for no frames makes no recorder: no GL context, no mesh, no encoder.
  std::unique_ptr<VideoRecorder> recorder;
  if (run.frames) {
    recorder = std::make_unique<VideoRecorder>(run.rig, run.video, *run.frames);
    if (const std::string note = recorder->note(); !note.empty() && control.note)
      control.note(note);
    options.observer = [&recorder](const StepView& view) { recorder->observe(view); };
  }
  options.stop = control.stop;
  options.progress = control.progress;

  RunResult result;
  result.chosen_time_step = run.chosen_time_step;
  const CompiledRig& rig = *run.rig;
  // `out` without `record`: the steps and samples stream to their files, none kept in memory.
  std::optional<RunFiles> files;
  if (!run.out.empty() && !run.record) {
    files.emplace(run.out, run.output, rig);
    RunOptions streamed = files->options();
    streamed.observer = std::move(options.observer);
    streamed.stop = options.stop;
    streamed.progress = options.progress;
    options = std::move(streamed);
  }
  result.summary = run_experiment(rig, options, &result.recording);
  // The video up to its last frame, playable, even when the run was interrupted.
  if (recorder)
    result.video =
        recorder->finish(VideoEnding{result.summary.failure.value_or(""), result.summary.duration});
  if (files) {
    files->finish(result.summary, result.recording);
    result.out = run.out;
  } else if (!run.out.empty()) {
    write_run_outputs(run.out, run.output, rig, result.summary, result.recording);
    result.out = run.out;
  }
  // The plot last, after the results it draws are written: its failure loses none.
  if (run.plot) {
    const std::string png = run.out + "/periods.png";
    try {
      run_plot_script("plot_periods.py", {run.out, png});
      result.plot = png;
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

}  // namespace fl
