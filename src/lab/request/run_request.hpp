// A run, as every front end asks for it (`frictionlab run`, frictionlab.run, the browser's
// session): the scene and its overrides, the run's length, seed and accuracy, where its files go,
// what it keeps in memory, and the frames it draws. The request owns its defaults and its checks:
// prepare_run reads and checks every field before any work, reporting problems by field
// (lab/request/field_checks.hpp); execute_run runs what was prepared; the result says how the run
// ended (lab/request/outcome.hpp). Front ends only map their names onto the fields.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/scene_source.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/run_summary.hpp"
#include "lab/video/video_settings.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// A frame size: "1280x720", or {width, height}.
using FrameSizeInput = std::variant<std::string, std::array<int, 2>>;

struct RunRequest {
  SceneSource scene;                      // field "scene" (its own overrides included)
  std::vector<std::string> set;           // "set": more overrides, "key.path=value"
  std::optional<QuantityInput> duration;  // "duration": world.duration
  std::optional<std::int64_t> seed;       // "seed": world.seed
  std::optional<QuantityInput> accuracy;  // "accuracy": pick the step for this period bias
  std::string out;                        // "out": folder for the run's files
  bool plot = false;                      // "plot": out/periods.png (python3, matplotlib)
  bool record = false;                    // "record": keep every step's outputs in memory
  // The frames: "video" (.mp4, .gif or .webm), "frames" (a folder of PNGs), "still" (a PNG),
  // and what shapes them, each in the scene's `video` part otherwise.
  std::string video;
  std::string frames;
  std::string still;
  std::string gl;                            // "gl": osmesa, egl or auto
  std::optional<FrameSizeInput> size;        // "size"
  std::optional<int> fps;                    // "fps"
  std::optional<QuantityInput> slow_motion;  // "slow_motion"
  std::optional<std::string> camera;         // "camera": front, top, sensor or phone
  std::optional<QuantityInput> orbit;        // "orbit": an angular speed of video time
  std::optional<std::string> title;          // "title": turns the title card on
  std::string captions;                      // "captions": a captions file

  bool draws_frames() const { return !video.empty() || !frames.empty() || !still.empty(); }
};

// A run read and checked: the scene loaded (with the chosen step), the frames' request resolved,
// its files' places made ready. Made by prepare_run only.
struct PreparedRun {
  std::shared_ptr<const Scene> scene;      // as loaded, with the request's entries
  std::shared_ptr<const CompiledRig> rig;  // compiled once, at the chosen step
  OutputDesc output;                       // the scene's output part: which files `out` holds
  std::optional<double> chosen_time_step;  // s, when `accuracy` picked it
  std::optional<double> chosen_bias;       // its predicted integrator bias (relative)
  std::string chosen_step_why;             // what sized it, when `accuracy` picked it
  std::optional<VideoRequest> frames;      // when the run draws frames
  VideoDesc video;                         // and how: the scene's video part with the request's
  std::string out;
  bool plot = false;
  bool record = false;
  std::vector<std::string> warnings;  // for the front end to show (field_ref mentions)
};

// Reads and checks every field; throws RequestError (every problem by field) or InputError
// located in a file the request names (the scene, the captions).
PreparedRun prepare_run(const RunRequest& request);

// What a front end gives a run beyond the request: a stop flag (Ctrl-C, SIGTERM, a closed page),
// the progress of simulated time, and a place for notes (the GL back end chosen).
struct RunControl {
  const std::atomic<bool>* stop = nullptr;
  std::function<void(double t)> progress;  // every 1000 steps
  std::function<void(const std::string&)> note;
};

struct RunResult {
  RunSummary summary;
  RunRecording recording;            // what `record` (or `out`) asked to keep
  std::optional<VideoReport> video;  // when frames were drawn
  std::optional<double> chosen_time_step;
  std::string out;           // the folder written, if any
  std::string plot;          // the plot drawn, if any
  std::string plot_failure;  // why the plot could not be drawn (the run's files stand)

  Outcome outcome() const;
};

// Runs a prepared request. Throws VideoUnavailable when the frames cannot be drawn (before the
// physics runs). Never throws for the physics' own trouble: a guard is RunSummary::failure.
RunResult execute_run(const PreparedRun& run, const RunControl& control);

}  // namespace fl
