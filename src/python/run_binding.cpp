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
  py::object phones = py::none();
  std::optional<VideoReport> video;
  std::string plot_failure;
};

// An estimator's value that needs `n` accepted periods, or None with fewer (never 0).
// The estimator's mean (from one accepted period) and its spreads (from two:
// EstimatorReport::has_spread), None below.
std::optional<double> with_mean(const EstimatorReport& e, double value) {
  return e.periods_used >= 1 ? std::optional<double>(value) : std::nullopt;
}
std::optional<double> with_spread(const EstimatorReport& e, double value) {
  return e.has_spread() ? std::optional<double>(value) : std::nullopt;
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
    py::list phones;
    for (std::size_t i = 0; i < prepared.rig->phones.size(); ++i)
      phones.append(phone_array(
          i < recording.phones.size() ? std::move(recording.phones[i]) : std::vector<PhoneSample>{},
          prepared.rig->phones[i].sensor));
    result.phones = phones;
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
          "period", [](const EstimatorReport& e) { return with_mean(e, e.period); },
          "s, the mean period")
      .def_property_readonly(
          "period_std", [](const EstimatorReport& e) { return with_spread(e, e.period_std); },
          "s, standard deviation of the periods")
      .def_property_readonly(
          "period_std_error",
          [](const EstimatorReport& e) { return with_spread(e, e.period_std_error); },
          "s, standard error of the mean")
      .def_property_readonly(
          "mu_k", [](const EstimatorReport& e) { return with_mean(e, e.mu_k); },
          "from the mean period, thin formula (the paper's)")
      .def_property_readonly(
          "mu_k_err_worst",
          [](const EstimatorReport& e) { return with_spread(e, e.mu_k_err_worst); },
          "mu_k (dl/l + 2 dT/T)")
      .def_property_readonly(
          "mu_k_err_quadrature",
          [](const EstimatorReport& e) { return with_spread(e, e.mu_k_err_quadrature); },
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
  py::class_<S> summary(m, "RunSummary",
                        R"(What one run found (lab/run/run_summary.hpp), SI throughout.

A value the run did not measure is None, never 0. str(summary) is the summary
`frictionlab run` prints; summary.json() the object `frictionlab run --json` prints.)");
  // Every plain value from the one declaration of a run's fields (lab/run/summary_fields.hpp); the
  // typed ones (enums and reports) below.
  for (const SummaryField& f : summary_fields()) {
    if (f.python == nullptr || f.python_type != nullptr) continue;
    const auto get = f.get;
    summary.def_property_readonly(
        f.python, [get](const S& s) { return python_field(get(s)); },
        field_doc(f.unit, f.meaning, f.null_when).c_str());
  }
  summary.def_readonly("regime", &S::regime, "the regime the run diagnosed")
      .def_readonly("regime_theory", &S::regime_theory,
                    "the regime the closed forms give, where the run has numbers to hold "
                    "against them")
      .def_readonly("mu_k_source", &S::mu_k_source, "where mu_k comes from")
      .def_readonly("estimator", &S::estimator, "the estimator's report, or None without a sensor")
      .def_readonly("drive", &S::drive, "the motor and gears, or None for the ideal drive")
      .def_readonly("warming", &S::warming, "rollers warming over the run, or None")
      .def_readonly("paper_period", &S::paper_period, "T +- dT the paper measured [s], or None")
      .def_readonly("paper_mu_k", &S::paper_mu_k, "mu_k +- d mu_k the paper printed, or None")
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
                if (f.json != nullptr && key == f.json) return py::object(py::none());
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
phones: a list, one structured array per phone of the scene, in its order: t_s and, in the
  phone's axes, bx_t, by_t, bz_t (a magnetometer, T) or ax_m_s2, ay_m_s2, az_m_s2 (an
  accelerometer), each sample before phyphox's CSV rounds it.
Each is None when the run was made with record=False. Each column (result.trajectory["x_m"])
is a view, not a copy.)")
      .def_readonly("trajectory", &PythonRunResult::trajectory)
      .def_readonly("hall", &PythonRunResult::hall)
      .def_readonly("cycles", &PythonRunResult::cycles)
      .def_readonly("periods", &PythonRunResult::periods)
      .def_readonly("jump_list", &PythonRunResult::jump_list)
      .def_readonly("phones", &PythonRunResult::phones)
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
