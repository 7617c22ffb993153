// frictionlab.run: one simulation of a scene, as `frictionlab run` does it (the same loader,
// compiled rig, experiment and outputs), returning the typed summary (lab/run/run_summary.hpp) with
// the trajectory and the Hall samples as NumPy arrays. The GIL is released while the world steps,
// so runs in several Python threads use several cores.
#include <dlfcn.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lab/request/run_request.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab/run/summary_fields.hpp"
#include "lab/video/video_module.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/field_spelling.hpp"
#include "python/interrupt_watch.hpp"
#include "python/json_values.hpp"
#include "python/loaded_scene.hpp"
#include "python/record_arrays.hpp"

namespace fl::python {
namespace {

// A run's summary with what it recorded.
struct PythonRunResult : RunSummary {
  py::object trajectory = py::none();
  py::object hall = py::none();
  py::object cycles = py::none();
  py::object periods = py::none();
  py::object jump_list = py::none();
  std::optional<VideoReport> video;
  std::string plot_failure;
};

// An estimator's value that needs `n` accepted periods, or None with fewer (never 0).
std::optional<double> with_periods(const EstimatorReport& e, int n, double value) {
  return e.periods_used >= n ? std::optional<double>(value) : std::nullopt;
}

// A top-level value copied from the estimator (mu_k_estimator and its uncertainties): None where
// the estimator accepted too few periods to measure it.
std::optional<double> from_estimator(const RunSummary& s, int n, const std::optional<double>& v) {
  if (!v || !s.estimator || s.estimator->periods_used < n) return std::nullopt;
  return v;
}

// The video module beside this Python module (an installed copy), else the build's: where the
// recorder looks when $FRICTIONLAB_VIDEO_MODULE does not say (it would look beside the running
// executable, which is python3).
void find_video_module() {
  if (const char* env = std::getenv(kVideoModuleVariable); env != nullptr && *env != '\0') return;
  std::string path = FRICTIONLAB_PYTHON_VIDEO_MODULE;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&find_video_module), &info) != 0 &&
      info.dli_fname != nullptr) {
    const std::filesystem::path beside =
        std::filesystem::path(info.dli_fname).parent_path() / "frictionlab-video.so";
    std::error_code ec;
    if (std::filesystem::is_regular_file(beside, ec)) path = beside.string();
  }
  if (!path.empty()) setenv(kVideoModuleVariable, path.c_str(), 0);
}

// A frame size: "1280x720" or (1280, 720).
using FrameSize = std::variant<std::string, std::array<int, 2>>;

PythonRunResult run(const SceneArgument& scene_to_run, const std::optional<Quantity>& duration,
                    std::optional<std::int64_t> seed, const std::optional<Path>& out_folder,
                    const std::optional<Quantity>& accuracy, bool record, bool plot,
                    const std::optional<Path>& video, const std::optional<Path>& frames,
                    const std::optional<Path>& still, const std::optional<std::string>& gl,
                    std::optional<int> fps, const std::optional<FrameSize>& size,
                    const std::optional<Quantity>& slow_motion,
                    const std::optional<std::string>& camera,
                    const std::optional<std::string>& title, const std::optional<Quantity>& orbit,
                    const std::optional<Path>& captions) {
  RunRequest request;
  request.scene = scene_source_argument(scene_to_run);
  request.duration = duration;
  request.seed = seed;
  request.accuracy = accuracy;
  if (out_folder) request.out = out_folder->string();
  request.record = record;
  request.plot = plot;
  if (video) request.video = video->string();
  if (frames) request.frames = frames->string();
  if (still) request.still = still->string();
  if (gl) request.gl = *gl;
  request.fps = fps;
  request.size = size;
  request.slow_motion = slow_motion;
  request.camera = camera;
  request.title = title;
  request.orbit = orbit;
  if (captions) request.captions = captions->string();
  const PreparedRun prepared = prepare_run(request);
  if (prepared.frames) find_video_module();
  for (const std::string& warning : prepared.warnings)
    PyErr_WarnEx(PyExc_UserWarning, spelled(warning).c_str(), 1);

  PythonRunResult result;
  RunResult done;
  InterruptWatch watch;
  {
    const py::gil_scoped_release released;
    RunControl control;
    control.stop = watch.flag();
    control.progress = [&watch](double) { watch.check(); };
    done = execute_run(prepared, control);
  }
  // Ctrl-C: the run kept what it did (its files are written); Python hears KeyboardInterrupt.
  watch.raise();
  static_cast<RunSummary&>(result) = std::move(done.summary);
  result.video = std::move(done.video);
  result.plot_failure = done.plot_failure;
  if (record) {
    const bool sensor = prepared.rig->sensor.has_value();
    RunRecording& recording = done.recording;
    result.trajectory = trajectory_array(std::move(recording.trajectory));
    if (sensor) result.hall = hall_array(std::move(recording.hall));
    result.cycles = cycles_array(std::move(recording.cycles));
    if (sensor) result.periods = periods_array(std::move(recording.periods));
    result.jump_list = jumps_array(std::move(recording.jumps));
  }
  return result;
}

void bind_reports(py::module_& m) {
  py::class_<EstimatorReport>(
      m, "EstimatorReport",
      "The period the rig's estimator measured from the simulated Hall signal. A value that\n"
      "needs more accepted periods than there were is None: the period and mu_k one, their\n"
      "spread and uncertainties two.")
      .def_readonly("periods_used", &EstimatorReport::periods_used, "accepted periods")
      .def_readonly("periods_discarded", &EstimatorReport::periods_discarded)
      .def_readonly("pulses", &EstimatorReport::pulses)
      .def_property_readonly(
          "period", [](const EstimatorReport& e) { return with_periods(e, 1, e.period); },
          "s, the mean period")
      .def_property_readonly(
          "period_std", [](const EstimatorReport& e) { return with_periods(e, 2, e.period_std); },
          "s, standard deviation of the periods")
      .def_property_readonly(
          "period_std_error",
          [](const EstimatorReport& e) { return with_periods(e, 2, e.period_std_error); },
          "s, standard error of the mean")
      .def_property_readonly(
          "mu_k", [](const EstimatorReport& e) { return with_periods(e, 1, e.mu_k); },
          "from the mean period, thin formula (the paper's)")
      .def_property_readonly(
          "mu_k_err_worst",
          [](const EstimatorReport& e) { return with_periods(e, 2, e.mu_k_err_worst); },
          "mu_k (dl/l + 2 dT/T)")
      .def_property_readonly(
          "mu_k_err_quadrature",
          [](const EstimatorReport& e) { return with_periods(e, 2, e.mu_k_err_quadrature); },
          "mu_k sqrt((dl/l)^2 + (2 dT/T)^2)");

  py::class_<DriveReport>(m, "DriveReport", "The motor and gears over the run (SI, means).")
      .def_readonly("motor_speed", &DriveReport::motor_speed, "rad/s, in the motor's sense")
      .def_readonly("motor_torque", &DriveReport::motor_torque, "N m")
      .def_readonly("roller_speeds", &DriveReport::roller_speeds, "rad/s about +y, each roller")
      .def_readonly("gearbox_ratio", &DriveReport::gearbox_ratio, "the design's speed-up")
      .def_readonly("turning_fraction", &DriveReport::turning_fraction,
                    "the share of the steps in which the motor and both rollers turned")
      .def_readonly("speed_ratio", &DriveReport::speed_ratio,
                    "|roller 0| / |motor| while turning, None if the train never turned")
      .def_readonly("speed_ratio_error", &DriveReport::speed_ratio_error,
                    "largest |ratio / design - 1| while turning, None if it never turned")
      .def_readonly("senses_opposite", &DriveReport::senses_opposite,
                    "the rollers turned opposite ways at every turning step; None if none")
      .def_readonly("load_torque", &DriveReport::load_torque,
                    "N m, the torque the plate's friction takes from the rollers");

  py::class_<WarmingWindow>(m, "WarmingWindow", "The estimator's accepted periods in a window.")
      .def_readonly("periods", &WarmingWindow::periods, "how many")
      .def_readonly("period", &WarmingWindow::period, "s, their mean")
      .def_readonly("mu_k", &WarmingWindow::mu_k, "from the mean, the paper's formula");

  py::class_<WarmingReport>(m, "WarmingReport",
                            "Rollers warming over the run (friction.warming): their temperature, "
                            "mu_k,\nand the mu_k a student computes from the estimator's periods.")
      .def_readonly("start_temperature", &WarmingReport::start_temperature, "K")
      .def_readonly("room_temperature", &WarmingReport::room_temperature, "K")
      .def_readonly("time_constant", &WarmingReport::time_constant, "s")
      .def_readonly("hold", &WarmingReport::hold, "s at the start temperature first")
      .def_readonly("mu_k_start", &WarmingReport::mu_k_start)
      .def_readonly("mu_k_room", &WarmingReport::mu_k_room)
      .def_readonly("end_temperature", &WarmingReport::end_temperature, "K, at the run's end")
      .def_readonly("mu_k_end", &WarmingReport::mu_k_end)
      .def_readonly("mu_k_cold_paper_formula", &WarmingReport::mu_k_cold_paper_formula,
                    "the paper's formula on rollers that stay at the start's temperature")
      .def_readonly("first_10_periods", &WarmingReport::first_10_periods, "or None")
      .def_readonly("first_30_s", &WarmingReport::first_30_s, "or None")
      .def_readonly("whole_run", &WarmingReport::whole_run, "or None");

  py::class_<VideoReport>(m, "VideoReport", "The frames a run drew.")
      .def_readonly("frames", &VideoReport::frames, "title card included")
      .def_readonly("title_frames", &VideoReport::title_frames)
      .def_readonly("ending_frames", &VideoReport::ending_frames)
      .def_readonly("width", &VideoReport::width)
      .def_readonly("height", &VideoReport::height)
      .def_readonly("fps", &VideoReport::fps)
      .def_readonly("slow_motion", &VideoReport::slow_motion)
      .def_readonly("camera", &VideoReport::camera)
      .def_readonly("backend", &VideoReport::backend)
      .def_readonly("triangles", &VideoReport::triangles)
      .def_readonly("setup_seconds", &VideoReport::setup_seconds)
      .def_readonly("render_seconds", &VideoReport::render_seconds)
      .def_readonly("finish_seconds", &VideoReport::finish_seconds);
}

void bind_summary(py::module_& m) {
  using S = RunSummary;
  py::class_<S>(m, "RunSummary", R"(What one run found (lab/run/run_summary.hpp), SI throughout.

A value the run did not measure is None, never 0. str(summary) is the summary
`frictionlab run` prints; summary.json() the object `frictionlab run --json` prints.)")
      .def_readonly("scene", &S::scene)
      .def_readonly("seed", &S::seed)
      .def_readonly("spacing", &S::spacing, "l [m]")
      .def_readonly("mu_k_set", &S::mu_k_set, "the scene's mu_k")
      .def_readonly("h_c", &S::h_c, "m, the centre of mass above the contact line")
      .def_readonly("plate_mass", &S::plate_mass, "kg")
      .def_readonly("gravity", &S::gravity, "m/s^2")
      .def_readonly("temperature", &S::temperature, "K, of the rollers")
      .def_readonly("clock_error", &S::clock_error, "the sensor board's clock error, or None")
      .def_readonly("runout", &S::runout, "m, the rollers' run-out, or None for true rollers")
      .def_readonly("runout_threshold", &S::runout_threshold,
                    "m, the run-out above which theory has the plate hop, or None")
      .def_readonly("warming", &S::warming, "rollers warming over the run, or None")
      .def_readonly("time_step", &S::time_step, "s")
      .def_readonly("solver_iterations", &S::solver_iterations, "the iterations the run ended with")
      .def_readonly("solver_iterations_raised", &S::solver_iterations_raised,
                    "from what, to what and why the run raised them, or None")
      .def_readonly("duration", &S::duration, "s simulated")
      .def_readonly("steps", &S::steps)
      .def_property_readonly(
          "paper_material",
          [](const S& s) {
            return s.paper_material.empty() ? std::nullopt : std::optional(s.paper_material);
          },
          "the Table I key the scene took mu_k from, or None")
      .def_readonly("paper_period", &S::paper_period, "T +- dT the paper measured [s], or None")
      .def_readonly("paper_mu_k", &S::paper_mu_k, "mu_k +- d mu_k the paper printed, or None")
      .def_readonly("period_thin", &S::period_thin, "s, the paper's formula")
      .def_readonly("period_thick", &S::period_thick, "s; None without a restoring force")
      .def_readonly("predicted_integrator_bias", &S::predicted_integrator_bias,
                    "relative, -(omega dt)^2 / 24")
      .def_readonly("slip_threshold", &S::slip_threshold, "rad/s, roller speed for full slip")
      .def_readonly("regime", &S::regime, "the regime the run diagnosed")
      .def_readonly("regime_since", &S::regime_since, "s, when it began")
      .def_readonly("regime_evidence", &S::regime_evidence, "why")
      .def_readonly("clip_time", &S::clip_time, "s, clipped: when the first stick began")
      .def_readonly("amplitude_before_clip", &S::amplitude_before_clip, "m, clipped")
      .def_readonly("amplitude_clipped", &S::amplitude_clipped, "m, clipped: the steady amplitude")
      .def_readonly("stick_slip_period", &S::stick_slip_period, "s, stick-slip")
      .def_readonly("stick_slip_amplitude", &S::stick_slip_amplitude, "m, stick-slip")
      .def_readonly("stick_duration", &S::stick_duration, "s, stick-slip: one stick phase")
      .def_readonly("growth_rate", &S::growth_rate, "1/s, grows or decays: d ln A / dt")
      .def_readonly("e_folding_time", &S::e_folding_time, "s, grows or decays")
      .def_readonly("jumps", &S::jumps, "lift-offs and landings, or None if it never left")
      .def_readonly("first_jump_time", &S::first_jump_time, "s")
      .def_readonly("longest_jump", &S::longest_jump, "s")
      .def_readonly("highest_jump", &S::highest_jump, "m, the largest gap under the plate")
      .def_readonly("regime_theory", &S::regime_theory,
                    "the regime the closed forms give, where the run has numbers to hold "
                    "against them")
      .def_readonly("amplitude_clipped_theory", &S::amplitude_clipped_theory, "m, v_r / Omega")
      .def_readonly("stick_slip_period_theory", &S::stick_slip_period_theory, "s")
      .def_readonly("stick_slip_amplitude_theory", &S::stick_slip_amplitude_theory, "m")
      .def_readonly("stick_duration_theory", &S::stick_duration_theory, "s")
      .def_readonly("growth_rate_theory", &S::growth_rate_theory, "1/s")
      .def_readonly("period", &S::period,
                    "s, the headline period (the rig's estimator); None but for a harmonic "
                    "oscillation (period_withheld says why)")
      .def_readonly("mu_k_recovered", &S::mu_k_recovered, "from the period, thin formula")
      .def_readonly("mu_k_recovered_thick", &S::mu_k_recovered_thick,
                    "from the period, thick formula with the rig's h_c")
      .def_readonly("mu_k_source", &S::mu_k_source, "where mu_k comes from")
      .def_readonly("period_withheld", &S::period_withheld, "why there is no period, or None")
      .def_property_readonly(
          "mu_k_estimator", [](const S& s) { return from_estimator(s, 1, s.mu_k_estimator); },
          "the estimator's own mu_k (thin formula), harmonic oscillations only")
      .def_property_readonly(
          "mu_k_err_worst", [](const S& s) { return from_estimator(s, 2, s.mu_k_err_worst); },
          "its uncertainty, worst case")
      .def_property_readonly(
          "mu_k_err_quadrature",
          [](const S& s) { return from_estimator(s, 2, s.mu_k_err_quadrature); },
          "its uncertainty, in quadrature")
      .def_readonly("estimator", &S::estimator, "the estimator's report, or None without a sensor")
      .def_readonly("period_trajectory", &S::period_trajectory,
                    "s, the trajectory's own period (crossings of x = 0), harmonic only")
      .def_readonly("period_trajectory_err", &S::period_trajectory_err, "s, its standard error")
      .def_readonly("oscillation_centre", &S::oscillation_centre,
                    "m, the mean of the midpoints of successive turning points")
      .def_readonly("oscillation_centre_theory", &S::oscillation_centre_theory,
                    "m, a tilted rig's x_eq (0 on a level one)")
      .def_readonly("tilt", &S::tilt, "rad, world.tilt")
      .def_readonly("drift_speed", &S::drift_speed,
                    "m/s along +y, skewed axes' sideways drift over the run's second half; None "
                    "without skew")
      .def_readonly("drift_speed_theory", &S::drift_speed_theory,
                    "m/s, v_r sin(skew / 2); None without skew or with unequal speeds")
      .def_readonly("estimator_disagreement", &S::estimator_disagreement,
                    "the estimator's period against the trajectory's, beyond both "
                    "uncertainties, or None")
      .def_readonly("amplitude_start", &S::amplitude_start,
                    "m, first turning point; None when the run reached none")
      .def_readonly("amplitude_end", &S::amplitude_end,
                    "m, last turning point; None when the run reached none")
      .def_readonly("amplitude_drift_per_period", &S::amplitude_drift_per_period, "relative")
      .def_readonly("roller_speed", &S::roller_speed,
                    "rad/s, roller 0's (mean when driven or ramped)")
      .def_readonly("roller_speed_1", &S::roller_speed_1,
                    "rad/s, roller 1's (mean when driven or ramped)")
      .def_readonly("drive", &S::drive, "the motor and gears, or None for the ideal drive")
      .def_readonly("plate_speed_max", &S::plate_speed_max, "m/s")
      .def_readonly("slip_margin", &S::slip_margin, "roller surface speed / plate's largest speed")
      .def_readonly("min_normal_force", &S::min_normal_force, "N, over the run")
      .def_readonly("max_penetration", &S::max_penetration, "m")
      .def_readonly("failure", &S::failure, "what stopped the run, or None")
      .def_readonly("interrupted_at", &S::interrupted_at,
                    "s: where an interrupt ended the run before its duration, or None")
      .def_readonly("condition_period", &S::condition_period, "d ln mu / d ln T (thick formula)")
      .def_readonly("condition_spacing", &S::condition_spacing, "d ln mu / d ln l")
      .def_readonly("condition_h_c", &S::condition_h_c, "d ln mu / d ln h_c")
      .def_readonly("wall_s", &S::wall_s, "s of wall time")
      .def_readonly("real_time_factor", &S::real_time_factor)
      .def_readonly("steps_per_second", &S::steps_per_second)
      .def_property_readonly("harmonic", &S::harmonic,
                             "an oscillation whose period the paper's formula reads")
      .def(
          "json",
          [](const S& s) {
            nlohmann::json j = summary_json(s);
            j.update(timing_json(s));
            return python_value(j);
          },
          "The object `frictionlab run --json` prints (docs/cli.md): summary.json's keys and "
          "timing.json's.")
      .def(
          "__getitem__",
          [](const S& s, const std::string& key) {
            // Every field of the one table (lab/run/summary_fields.hpp) by its summary.json key,
            // a field added there included, with no binding of its own.
            const nlohmann::json j = summary_json(s);
            const auto it = j.find(key);
            if (it == j.end()) {
              for (const SummaryField& f : summary_fields())
                if (f.summary_key != nullptr && key == f.summary_key) return py::object(py::none());
              throw py::key_error("summary.json has no key \"" + key +
                                  "\" (docs/cli.md lists them)");
            }
            return python_value(*it);
          },
          py::arg("key"),
          "summary[\"period_s\"]: any key of summary.json (docs/cli.md), SI; None where the run "
          "has no value.")
      .def("__str__", [](const S& s) { return spelled(summary_text(s)); })
      .def("__repr__", [](const py::object& self) {
        const S& s = self.cast<const S&>();
        return "<frictionlab." + self.get_type().attr("__name__").cast<std::string>() + " '" +
               s.scene + "': " + regime_name(s.regime) +
               (s.period ? ", T = " + py::repr(py::float_(*s.period)).cast<std::string>() + " s"
                         : std::string()) +
               ">";
      });

  py::class_<PythonRunResult, S>(m, "RunResult",
                                 R"(A run's summary (RunSummary) with what it recorded.

trajectory: structured array, shape (steps + 1,), the start and every step; fields
  t_s, x_m, z_m, pitch_rad, vx_m_s, vz_m_s, pitch_rate_rad_s, y_m, yaw_rad (the plate's
  centre of mass), and per roller i = 0 (at x = -l/2), 1 (+l/2): touching{i}, stuck{i}
  (bool), normal{i}_n, friction{i}_n (forces on the plate over the step), penetration{i}_m,
  gap{i}_m (how far the plate is above the roller).
hall: structured array, shape (samples,): t_us (uint32, the sensor board's microsecond
  clock) and adc (uint16, counts); None for a scene without a sensor.
cycles: structured array, shape (cycles,): start_s, period_s, amplitude_m, x_min_m, x_max_m,
  surface_speed_m_s, stick_s (each complete cycle of the plate).
periods: structured array, shape (periods,): each period the rig's estimator judged, start_s,
  end_s, period_s, status (0 accepted, 1 an outlier, 2 at a broken turning point); None for a
  scene without a sensor.
jump_list: structured array, shape (jumps,): each time the plate left a roller, roller,
  start_s, end_s, height_m, roller_angle_rad, open (jumps.csv; `jumps` is their count).
Each is None when the run was made with record=False. Each column (result.trajectory["x_m"])
is a view, not a copy.)")
      .def_readonly("trajectory", &PythonRunResult::trajectory)
      .def_readonly("hall", &PythonRunResult::hall)
      .def_readonly("cycles", &PythonRunResult::cycles)
      .def_readonly("periods", &PythonRunResult::periods)
      .def_readonly("jump_list", &PythonRunResult::jump_list)
      .def_readonly("video", &PythonRunResult::video, "the frames drawn, or None")
      .def_property_readonly(
          "plot_failure",
          [](const PythonRunResult& r) {
            return r.plot_failure.empty() ? std::nullopt : std::optional(r.plot_failure);
          },
          "why plot=True drew no plot, or None");
}

}  // namespace

void bind_run(py::module_& m) {
  bind_reports(m);
  bind_summary(m);
  m.def("run", &run, py::arg("scene"), py::arg("duration") = py::none(),
        py::arg("seed") = py::none(), py::arg("out") = py::none(), py::kw_only(),
        py::arg("accuracy") = py::none(), py::arg("record") = true, py::arg("plot") = false,
        py::arg("video") = py::none(), py::arg("frames") = py::none(),
        py::arg("still") = py::none(), py::arg("gl") = py::none(), py::arg("fps") = py::none(),
        py::arg("size") = py::none(), py::arg("slow_motion") = py::none(),
        py::arg("camera") = py::none(), py::arg("title") = py::none(),
        py::arg("orbit") = py::none(), py::arg("captions") = py::none(),
        R"(Simulates a scene, as `frictionlab run SCENE` does; returns a RunResult.

scene: a Scene (load_scene) or a scene file's path.
duration: simulated time, "20s" or 20.0 (default: the scene's world.duration).
seed: the sensor's noise and jitter (world.seed; default the scene's).
  duration and seed load the scene again with world.duration and world.seed set, as
  `--duration` and `--set` do.
out: a folder to write what `frictionlab run --out` writes (summary.json, timing.json,
  trajectory.csv, hall.csv, cycles.csv, as the scene's output part asks).
accuracy: pick the largest time step whose predicted period bias is below this ("0.001%").
record: keep the trajectory, the Hall samples and the cycles as arrays (RunResult).
plot: with out, draw out/periods.png as `frictionlab run --plot` (python3 + matplotlib); a plot
  that fails leaves the results, and plot_failure says why.
video, frames, still, gl, fps, size, slow_motion, camera, title, orbit, captions: as
  `frictionlab run --video` and its options (orbit: "10deg/s" or rad/s; captions: a YAML file
  with a `captions:` list, replacing the scene's); without video, frames or still they are
  refused (a build with rendering only; InputError says what is missing).
  The video module is found through $FRICTIONLAB_VIDEO_MODULE, which is set to the one
  beside this module (or the build's) when it is not set.

The GIL is released while the world steps: runs in several threads run in parallel, each
giving the result a run on its own gives. Ctrl-C stops the run after its step, as it stops
`frictionlab run`: the files in out are written for the steps done (interrupted_at_s), and
KeyboardInterrupt is raised. A run that a guard stopped returns (failure says why; regime
NUMERICALLY_FAILED or LOST) rather than raising. Raises InputError for bad input, before any
work: everything `frictionlab run` refuses with exit status 2, an out, video or still that
cannot be written included.)");
}

}  // namespace fl::python
