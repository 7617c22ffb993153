#include "lab/run/run_monitors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

namespace fl {
namespace {

PlatePose pose_of(double t, const PlateState& s) {
  return PlatePose{t, s.x, s.z, s.pitch, s.vx, s.vz, s.pitch_rate, s.y, s.yaw};
}

}  // namespace

void RegimeGuard::start(const RigWorld& /*world*/, const PlateState& plate) {
  monitor_.start(plate);
}

std::optional<RunFailure> RegimeGuard::check(const StepContext& step) {
  return monitor_.observe(step.t, step.plate, step.contacts, step.surface_speeds,
                          step.world.roller_angles());
}

std::optional<RunFailure> ConvergenceGuard::check(const StepContext& step) {
  unconverged_ = convergence_.observe(step.t, step.previous, step.plate, step.contacts);
  if (!unconverged_) return std::nullopt;
  return RunFailure{Regime::kNumericallyFailed, step.t,
                    fmt::format("roller {}", unconverged_->roller), "normal force",
                    fmt::format("the contact solver did not converge at {} iterations: {}",
                                rig_.world.solver_iterations, unconverged_->describe())};
}

HallChannel::HallChannel(const CompiledRig& rig, RecordSink* keep,
                         std::vector<HallSample>* view_samples)
    : hall_(rig),
      estimator_(rig.rollers.spacing, rig.world.gravity),
      keep_(keep),
      view_samples_(view_samples) {}

void HallChannel::record(const StepContext& step) {
  hall_.sample_between(pose_of(step.t_previous, step.previous), pose_of(step.t, step.plate),
                       [this](const HallSample& sample) {
                         estimator_.add(sample);
                         if (keep_ != nullptr) keep_->hall_sample(sample);
                         if (view_samples_ != nullptr) view_samples_->push_back(sample);
                       });
}

void PhoneChannel::record(const StepContext& step) {
  signal_.sample_between(pose_of(step.t_previous, step.previous), pose_of(step.t, step.plate),
                         [this](const PhoneSample& sample) { keep_.phone_sample(phone_, sample); });
}

void RecordingSink::phone_sample(std::size_t phone, const PhoneSample& sample) {
  if (recording_.phones.size() <= phone) recording_.phones.resize(phone + 1);
  recording_.phones[phone].push_back(sample);
}

void CycleRecorder::start(const RigWorld& world, const PlateState& plate) {
  tracker_.add(0.0, plate.x, plate.vx, world.roller_surface_speeds());
}

void CycleRecorder::record(const StepContext& step) {
  tracker_.add(step.t, step.plate.x, step.plate.vx, step.surface_speeds);
}

void TrajectoryRecorder::start(const RigWorld& world, const PlateState& plate) {
  keep_.trajectory_row({0.0, plate, world.contacts()});
}

void TrajectoryRecorder::record(const StepContext& step) {
  keep_.trajectory_row({step.t, step.plate, step.contacts});
}

void RampSpeedAverage::record(const StepContext& step) {
  const std::array<double, 2> speeds = step.world.roller_speeds();
  sum_[0] += std::fabs(speeds[0]);
  sum_[1] += std::fabs(speeds[1]);
  ++steps_;
}

std::optional<double> RampSpeedAverage::mean(int roller) const {
  if (steps_ == 0) return std::nullopt;
  return sum_[static_cast<std::size_t>(roller)] / static_cast<double>(steps_);
}

void SidewaysDrift::record(const StepContext& step) {
  if (step.t < since_) return;
  // Times from `since` keep the sums well conditioned.
  const double t = step.t - since_, y = step.plate.y;
  n_ += 1.0;
  st_ += t;
  sy_ += y;
  stt_ += t * t;
  sty_ += t * y;
}

std::optional<double> SidewaysDrift::speed() const {
  const double spread = n_ * stt_ - st_ * st_;
  if (n_ < 2.0 || !(spread > 0.0)) return std::nullopt;
  return (n_ * sty_ - st_ * sy_) / spread;
}

RunExtremes::RunExtremes() : min_normal_force(std::numeric_limits<double>::infinity()) {}

void RunExtremes::record(const StepContext& step) {
  plate_speed_max = std::max(plate_speed_max, std::fabs(step.plate.vx));
  for (const RollerContact& c : step.contacts) {
    min_normal_force = std::min(min_normal_force, c.normal_force);
    max_penetration = std::max(max_penetration, c.penetration);
  }
}

DriveStats::DriveStats(const CompiledRig& rig) : radius_(rig.rollers.radius) {
  if (rig.drive) design_ratio_ = rig.drive->gearbox_ratio;
}

void DriveStats::record(const StepContext& step) {
  const std::optional<DriveState> state = step.world.drive();
  if (!state) return;
  const DriveState& d = *state;
  ++n_;
  motor_speed_ += std::fabs(d.motor_speed);
  motor_torque_ += d.motor_torque;
  roller_[0] += d.roller_speeds[0];
  roller_[1] += d.roller_speeds[1];
  // A stalled train has no ratio and no senses: only the steps in which all three turn count.
  if (d.motor_speed != 0.0 && d.roller_speeds[0] != 0.0 && d.roller_speeds[1] != 0.0) {
    ++turning_;
    const double ratio = std::fabs(d.roller_speeds[0] / d.motor_speed);
    ratio_ += ratio;
    ratio_error_ = std::max(ratio_error_, std::fabs(ratio / design_ratio_ - 1.0));
    opposite_ = opposite_ && d.roller_speeds[0] * d.roller_speeds[1] < 0.0;
  }
  // The plate's friction F_i (on the plate, along x) acts back on roller i's top: torque
  // -a F_i about y; counted positive when it opposes the roller's turning.
  for (int i = 0; i < 2; ++i) {
    const double sense = d.roller_speeds[static_cast<std::size_t>(i)] >= 0.0 ? 1.0 : -1.0;
    load_ += sense * radius_ * step.contacts[static_cast<std::size_t>(i)].friction_force;
  }
}

DriveReport DriveStats::report() const {
  DriveReport r;
  const double n = std::max<double>(1.0, static_cast<double>(n_));
  r.motor_speed = motor_speed_ / n;
  r.motor_torque = motor_torque_ / n;
  r.roller_speeds = {roller_[0] / n, roller_[1] / n};
  r.gearbox_ratio = design_ratio_;
  r.turning_fraction = static_cast<double>(turning_) / n;
  if (turning_ > 0) {
    r.speed_ratio = ratio_ / static_cast<double>(turning_);
    r.speed_ratio_error = ratio_error_;
    r.senses_opposite = opposite_;
  }
  r.load_torque = load_ / n;
  return r;
}

StepObserver::StepObserver(std::function<void(const StepView&)> observer,
                           const RegimeMonitor* monitor)
    : observer_(std::move(observer)) {
  view_.monitor = monitor;
}

void StepObserver::start(const RigWorld& world, const PlateState& plate) {
  show(0.0, plate, world.contacts(), world);
}

void StepObserver::record(const StepContext& step) {
  show(step.t, step.plate, step.contacts, step.world);
}

void StepObserver::show(double t, const PlateState& plate,
                        const std::array<RollerContact, 2>& contacts, const RigWorld& world) {
  view_.t = t;
  view_.plate = plate;
  view_.contacts = contacts;
  view_.roller_angles = world.roller_angles();
  view_.roller_speeds = world.roller_speeds();
  view_.drive = world.drive();
  view_.shafts = world.shafts();
  observer_(view_);
  view_.new_samples.clear();
}

}  // namespace fl
