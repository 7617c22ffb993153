// The seam between the frictionlab executable and the video module, frictionlab-video.so: the
// shared object that holds the renderer (and through it OSMesa, libav and assimp), opened with
// dlopen only when a run asks for frames. Sweeps, MPI and the plain commands never load it.
//
// Only these cross: the compiled rig (the run's own, not compiled again), the video's settings and
// the request, each step as a VideoStep (copied from the run's StepView by the recorder,
// video_recorder.cpp) and the report, so the module does not depend on the experiment's types. The
// module exports one C function, kVideoModuleEntry, returning its VideoModule; the executable
// refuses a module whose VideoModuleAbi differs from its own (built from other sources: a coarse
// check of the interface's version and the sizes of what crosses).
//
// Where the executable looks: $FRICTIONLAB_VIDEO_MODULE if set, else frictionlab-video.so in the
// folder of the running executable (/proc/self/exe), where the build puts it.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lab/video/video_settings.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// The rig's estimator as a frame shows it.
struct VideoEstimate {
  int pulses = 0;
  int periods_used = 0;
  double period = 0.0;              // s, mean (when periods_used > 0)
  double period_std = 0.0;          // s
  double mu_k = 0.0;                // from the mean period, thin formula
  double mu_k_err_worst = 0.0;      // the paper's d mu/mu = dl/l + 2 dT/T
  std::vector<double> pulse_times;  // s, every pulse detected so far
  // s, the pulses the estimator learned the signal from (not timed; hall_estimator.hpp)
  std::vector<double> learning_pulse_times;
  bool signal_learned = false;  // the estimator times pulses
  bool geometry_known = false;  // it has recognised one pulse or a pair per period
  // s, before the geometry is known: the periods the timed pulses give (hall_estimator.hpp)
  std::vector<double> provisional_periods;
  int periods_discarded = 0;
  // The periods the estimator discarded so far (a jump bent a pulse, a pulse went missing): from,
  // to [s].
  std::vector<std::array<double, 2>> discarded;
  // s, the turning points its periods run between (the midpoints of its pulse groups), in order.
  std::vector<double> turning_points;
};

// One Hall sample: time and ADC counts.
struct VideoHallSample {
  double t = 0.0;    // s
  double adc = 0.0;  // counts
};

// One roller's contact with the plate as the solver left it (physics/rig_world.hpp).
struct VideoContact {
  bool touching = false;
  double normal_force = 0.0;    // N, pushing the plate up
  double friction_force = 0.0;  // N, along +x on the plate
  double point_x = 0.0;         // m, where the roller touches the plate, world x
  double point_z = 0.0;         // m, world z
};

// What a frame needs of one physics step.
struct VideoStep {
  double t = 0.0;                          // s
  double plate_x = 0.0;                    // m, the plate's centre of mass
  double plate_y = 0.0;                    // m
  double plate_z = 0.0;                    // m
  double pitch = 0.0;                      // rad about +y
  double yaw = 0.0;                        // rad about +z
  double plate_vx = 0.0;                   // m/s, the centre of mass's speed along x
  std::array<VideoContact, 2> contacts{};  // roller 0 (at x = -l/2), roller 1
  // Every shaft's angle (unwrapped) and speed about +y, in drive_layout order (rollers first);
  // for a scene without a drive the two rollers.
  std::vector<double> shaft_angles;          // rad
  std::vector<double> shaft_speeds;          // rad/s
  std::optional<double> motor_speed;         // rad/s (scenes with a drive)
  double roller_speed = 0.0;                 // rad/s about +y, roller 0
  std::vector<VideoHallSample> new_samples;  // the Hall samples taken during this step
  std::optional<VideoEstimate> estimate;     // the rig's estimator (scenes with a sensor)
  std::string
      regime;  // the regime diagnosed so far, with when it began (lab/run/regime_monitor.hpp)
};

// The frames of one run: what VideoRecorder forwards to.
class VideoEngine {
 public:
  VideoEngine() = default;
  VideoEngine(const VideoEngine&) = delete;
  VideoEngine& operator=(const VideoEngine&) = delete;
  virtual ~VideoEngine() = default;

  // Takes each step (and the one at t = 0) and draws every frame whose time it has passed.
  virtual void observe(const VideoStep& step) = 0;
  // Draws the ending (a guard's banner, the end card), writes the still, flushes and closes the
  // video and the frames. Called once, after the run.
  virtual VideoReport finish(const VideoEnding& ending) = 0;
  // A line worth telling before the run, or empty: the GL back end "auto" fell back to and why.
  virtual std::string note() const = 0;
};

// Makes the engine: creates the GL context, builds and uploads the rig, opens the sinks. `video`
// is the scene's video settings with the request's (effective_video). Throws VideoUnavailable,
// InputError. Defined in the video library (rig_video.cpp), which the module and the tests link.
std::unique_ptr<VideoEngine> make_video_engine(std::shared_ptr<const CompiledRig> rig,
                                               const VideoDesc& video, const VideoRequest& request);

// Raise when anything that crosses the seam changes.
inline constexpr int kVideoModuleVersion = 5;

struct VideoModuleAbi {
  int version = kVideoModuleVersion;
  std::size_t rig_size = sizeof(CompiledRig);
  std::size_t video_size = sizeof(VideoDesc);
  std::size_t request_size = sizeof(VideoRequest);
  std::size_t step_size = sizeof(VideoStep);
  std::size_t report_size = sizeof(VideoReport);
  std::size_t ending_size = sizeof(VideoEnding);

  bool operator==(const VideoModuleAbi&) const = default;
};

struct VideoModule {
  VideoModuleAbi abi;
  std::unique_ptr<VideoEngine> (*make_engine)(std::shared_ptr<const CompiledRig> rig,
                                              const VideoDesc& video, const VideoRequest& request);
};

// The name of the module's entry: extern "C" const VideoModule* frictionlab_video_module().
inline constexpr const char* kVideoModuleEntry = "frictionlab_video_module";
// The variable that names the module's file instead of the one next to the executable.
inline constexpr const char* kVideoModuleVariable = "FRICTIONLAB_VIDEO_MODULE";

// The executable's side (video_module_loader.cpp): the module, opened once and kept for the
// process's life. Throws VideoUnavailable when this build has no rendering, or the module is
// missing, cannot be opened, or was built from other sources.
const VideoModule& load_video_module();

}  // namespace fl
