// A run is a small loop over monitors (lab/run/experiment.cpp), as a simulator runs its monitors:
// after each step every monitor is asked whether the step may stand (the guards: the regime's
// and the contact solver's), then every monitor keeps what it needs of it (the Hall sensor and
// the rig's estimator, the recordings, the drive's figures, the extremes, the video's view). The
// loop knows none of them by name; the run builds only those its scene and options name, and
// reads what each found when the loop is done.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "core/cycle_tracker.hpp"
#include "lab/run/experiment.hpp"
#include "lab/run/hall_estimator.hpp"
#include "lab/run/regime_monitor.hpp"
#include "lab/run/run_summary.hpp"
#include "lab/run/solver_convergence.hpp"
#include "physics/rig_world.hpp"
#include "sensor/hall_signal.hpp"

namespace fl {

// What a monitor sees after a step.
struct StepContext {
  double t = 0.0;           // s, after the step
  double t_previous = 0.0;  // s, before it
  const PlateState& plate;
  const PlateState& previous;
  const std::array<RollerContact, 2>& contacts;
  const std::array<double, 2>& surface_speeds;  // m/s, each roller's surface
  const RigWorld& world;
};

class RunMonitor {
 public:
  virtual ~RunMonitor() = default;
  // At t = 0, before the first step.
  virtual void start(const RigWorld& /*world*/, const PlateState& /*plate*/) {}
  // After a step, before it is kept: a failure stops the run, and the step is not recorded.
  virtual std::optional<RunFailure> check(const StepContext& /*step*/) { return std::nullopt; }
  // After a step every guard passed.
  virtual void record(const StepContext& /*step*/) {}
};

// The regime's guard and diagnosis (lab/run/regime_monitor.hpp).
class RegimeGuard final : public RunMonitor {
 public:
  explicit RegimeGuard(const CompiledRig& rig) : monitor_(rig) {}
  void start(const RigWorld& world, const PlateState& plate) override;
  std::optional<RunFailure> check(const StepContext& step) override;
  const RegimeMonitor& monitor() const { return monitor_; }

 private:
  RegimeMonitor monitor_;
};

// The contact solver's convergence (lab/run/solver_convergence.hpp): a step whose normal forces
// do not balance the plate stops the run; `unconverged` says where.
class ConvergenceGuard final : public RunMonitor {
 public:
  explicit ConvergenceGuard(const CompiledRig& rig) : rig_(rig), convergence_(rig) {}
  std::optional<RunFailure> check(const StepContext& step) override;
  const std::optional<SolverResidual>& unconverged() const { return unconverged_; }

 private:
  const CompiledRig& rig_;
  SolverConvergence convergence_;
  std::optional<SolverResidual> unconverged_;
};

// The Hall sensor sampled between the steps, each sample into the rig's estimator (and to the
// recording and the video's view when they want it).
class HallChannel final : public RunMonitor {
 public:
  // `keep` (when not null) receives every sample, as does `view_samples`.
  HallChannel(const CompiledRig& rig, RecordSink* keep, std::vector<HallSample>* view_samples);
  void record(const StepContext& step) override;
  const HallEstimator& estimator() const { return estimator_; }

 private:
  HallSignal hall_;
  HallEstimator estimator_;
  RecordSink* keep_;
  std::vector<HallSample>* view_samples_;
};

// Each phone's sensor sampled between the steps (sensor/phone_signals.hpp), each sample kept.
class PhoneChannel final : public RunMonitor {
 public:
  PhoneChannel(const CompiledRig& rig, std::size_t phone, RecordSink& keep)
      : signal_(rig, phone), phone_(phone), keep_(keep) {}
  void record(const StepContext& step) override;

 private:
  PhoneSignal signal_;
  std::size_t phone_;
  RecordSink& keep_;
};

// Every complete cycle of the plate (cycles.csv).
class CycleRecorder final : public RunMonitor {
 public:
  void start(const RigWorld& world, const PlateState& plate) override;
  void record(const StepContext& step) override;
  const std::vector<CycleRecord>& cycles() const { return tracker_.cycles(); }

 private:
  CycleTracker tracker_;
};

// Every step's state (trajectory.csv).
class TrajectoryRecorder final : public RunMonitor {
 public:
  explicit TrajectoryRecorder(RecordSink& keep) : keep_(keep) {}
  void start(const RigWorld& world, const PlateState& plate) override;
  void record(const StepContext& step) override;

 private:
  RecordSink& keep_;
};

// A run's records kept in memory.
class RecordingSink final : public RecordSink {
 public:
  explicit RecordingSink(RunRecording& recording) : recording_(recording) {}
  void trajectory_row(const TrajectoryRow& row) override { recording_.trajectory.push_back(row); }
  void hall_sample(const HallSample& sample) override { recording_.hall.push_back(sample); }
  void phone_sample(std::size_t phone, const PhoneSample& sample) override;
  void restart() override { recording_ = RunRecording{}; }

 private:
  RunRecording& recording_;
};

// The ramped rollers' speed, averaged over the run's steps [rad/s].
class RampSpeedAverage final : public RunMonitor {
 public:
  void record(const StepContext& step) override;
  // Each roller's mean |speed| over the run [rad/s] (index 0 at -l/2).
  std::optional<double> mean(int roller = 0) const;

 private:
  std::array<double, 2> sum_{};
  long long steps_ = 0;
};

// The plate's sideways drift (skewed axes): the slope of y against t, fitted by least squares over
// the steps from `since` [s] on (after the slip along y has died out) [m/s].
class SidewaysDrift final : public RunMonitor {
 public:
  explicit SidewaysDrift(double since) : since_(since) {}
  void record(const StepContext& step) override;
  // Null with fewer than two steps fitted.
  std::optional<double> speed() const;

 private:
  double since_;
  double n_ = 0.0, st_ = 0.0, sy_ = 0.0, stt_ = 0.0, sty_ = 0.0;
};

// The plate's largest speed, the smallest normal force and the deepest penetration.
class RunExtremes final : public RunMonitor {
 public:
  void record(const StepContext& step) override;
  double plate_speed_max = 0.0;  // m/s
  double min_normal_force;       // N (infinity before the first step)
  double max_penetration = 0.0;  // m
  RunExtremes();
};

// The motor and gears: running means over the steps, the ratio and senses over those in which
// the train turned.
class DriveStats final : public RunMonitor {
 public:
  explicit DriveStats(const CompiledRig& rig);
  void record(const StepContext& step) override;
  DriveReport report() const;

 private:
  double radius_ = 0.0;
  double design_ratio_ = 1.0;
  long long n_ = 0, turning_ = 0;
  double motor_speed_ = 0.0, motor_torque_ = 0.0, ratio_ = 0.0, ratio_error_ = 0.0, load_ = 0.0;
  std::array<double, 2> roller_{};
  bool opposite_ = true;
};

// The run's observer (a video): the world after each step, between two steps' poses.
class StepObserver final : public RunMonitor {
 public:
  StepObserver(std::function<void(const StepView&)> observer, const RegimeMonitor* monitor);
  // The rig's estimator the view shows live (a scene with a sensor).
  void set_estimator(const HallEstimator* estimator) { view_.estimator = estimator; }
  void start(const RigWorld& world, const PlateState& plate) override;
  void record(const StepContext& step) override;
  // Where the Hall channel puts the samples of a step for the view.
  std::vector<HallSample>* new_samples() { return &view_.new_samples; }

 private:
  void show(double t, const PlateState& plate, const std::array<RollerContact, 2>& contacts,
            const RigWorld& world);
  std::function<void(const StepView&)> observer_;
  StepView view_;
};

}  // namespace fl
