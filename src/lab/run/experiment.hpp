// One run of a compiled rig: builds the world from exactly what the scene names, steps it,
// streams the simulated Hall samples into the rig's period estimator, follows the trajectory's
// own period and the regime, and summarises the run (lab/run/run_summary.hpp) against the analytic
// model.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/cycle_tracker.hpp"
#include "estimator/host_estimator.hpp"
#include "lab/run/regime_monitor.hpp"
#include "lab/run/run_summary.hpp"
#include "physics/rig_world.hpp"
#include "scene/compiled_rig.hpp"
#include "sensor/hall_signal.hpp"
#include "sensor/phone_signals.hpp"

namespace fl {

struct TrajectoryRow {
  double t = 0.0;  // s
  PlateState plate;
  std::array<RollerContact, 2> rollers;
};

struct RunRecording {
  std::vector<TrajectoryRow> trajectory;         // every step, when asked for
  std::vector<HallSample> hall;                  // every sample, when asked for
  std::vector<std::vector<PhoneSample>> phones;  // each phone's samples, when asked for
  std::vector<CycleRecord> cycles;  // every complete cycle of the plate, when asked for
  std::vector<PlateJump> jumps;     // every jump, when the run had jumps
  // Every period the rig's estimator judged (accepted or rejected), when the Hall samples are
  // recorded.
  std::vector<EstimatedPeriod> periods;
};

class HallEstimator;

// Where a run's step-by-step records go: into a RunRecording, or into a run's files as it goes
// (lab/run/run_files.hpp), which keeps no step in memory.
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual void trajectory_row(const TrajectoryRow& row) = 0;
  virtual void hall_sample(const HallSample& sample) = 0;
  // A sample of the rig's phone `phone` (CompiledRig::phones).
  virtual void phone_sample(std::size_t phone, const PhoneSample& sample) = 0;
  // The run starts again from t = 0 (at more solver iterations): what came so far is forgotten.
  virtual void restart() = 0;
};

// What a run looks like after each step, for an observer (the video renderer): everything needed
// to draw the rig and its overlays at any instant between two steps.
struct StepView {
  double t = 0.0;  // s
  PlateState plate;
  std::array<double, 2> roller_angles{};     // rad about +y since the start
  std::array<double, 2> roller_speeds{};     // rad/s about +y
  std::optional<DriveState> drive;           // the motor and gears, when the scene has a drive
  std::vector<ShaftState> shafts;            // the drive layout's shafts (scene/drive_layout.hpp)
  std::array<RollerContact, 2> contacts{};   // each roller's contact with the plate, as solved
  std::vector<HallSample> new_samples;       // the Hall samples taken during this step
  const HallEstimator* estimator = nullptr;  // the rig's estimator, live (null without a sensor)
  const RegimeMonitor* monitor = nullptr;    // the run's regime diagnosis, live
};

struct RunOptions {
  bool record_trajectory = false;
  bool record_hall = false;
  bool record_cycles = false;
  bool record_phones = false;
  // When set, the trajectory, Hall and phone samples asked for go here, not into the recording
  // (whose cycles, periods and jumps are kept as before).
  RecordSink* stream = nullptr;
  // Called after every step (and once at t = 0) when set.
  std::function<void(const StepView&)> observer;
  // When set and true, the run ends after its current step (RunSummary::interrupted_at); the
  // outputs hold every step up to it.
  const std::atomic<bool>* stop = nullptr;
  // Called every 1000 steps with the simulated time [s], when set.
  std::function<void(double)> progress;
};

struct SolverResidual;

// One run, a step at a time: what run_experiment loops over, and what a live front end (the
// browser's session) steps at the pace it shows. It builds the world and only the monitors the
// scene and the options name. The rig, the options and the recording must outlive it.
class RunLoop {
 public:
  RunLoop(const CompiledRig& rig, const RunOptions& options, RunRecording* recording = nullptr);
  RunLoop(const RunLoop&) = delete;
  RunLoop& operator=(const RunLoop&) = delete;
  ~RunLoop();

  // One step (the observer, when set, sees it); false once the run has ended: its duration
  // reached, a guard stopped it, or `stop` was raised (checked before the step).
  bool step();
  bool ended() const;
  double time() const;  // s, simulated
  // The run's summary: call once, when it has ended (or to end it where it stands). `unconverged`
  // is set when the solver's convergence check stopped it.
  RunSummary finish(std::optional<SolverResidual>& unconverged);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A run whose contact solver does not converge (lab/run/solver_convergence.hpp) starts again at
// twice the solver iterations, up to this; beyond it, it stops with a numerical failure.
inline constexpr int kMaxSolverIterations = 1280;  // 10 doubled seven times

// Runs a compiled rig for its scene's duration. Never throws for the physics' own trouble: a
// guard that stops the run is RunSummary::failure.
RunSummary run_experiment(const CompiledRig& rig, const RunOptions& options,
                          RunRecording* recording = nullptr);
// The same for a scene, compiled first.
RunSummary run_experiment(const Scene& scene, const RunOptions& options,
                          RunRecording* recording = nullptr);

}  // namespace fl
