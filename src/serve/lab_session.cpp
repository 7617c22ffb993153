#include "serve/lab_session.hpp"

#include <malloc.h>

#include <algorithm>
#include <stdexcept>

#include "lab/run/summary_fields.hpp"
#include "serve/api_json.hpp"
#include "serve/api_requests.hpp"

namespace fl::serve {
namespace {

constexpr double kFrame = 1.0 / 30;   // s of simulated time a single step advances
constexpr double kMostPerTick = 0.1;  // s of simulated time, whatever the wall clock did

}  // namespace

LabSession::LabSession(std::string scene, PreparedSession prepared, std::string name)
    : scene_(std::move(scene)),
      prepared_(std::move(prepared)),
      name_(std::move(name)),
      run_(std::make_unique<LiveRun>(prepared_.rig, prepared_.output)) {}

LabSession::~LabSession() {
  run_.reset();
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

LabSession::Tick LabSession::tick(Clock::time_point now) {
  const std::lock_guard lock(mutex_);
  last_seen_ = now;
  if (playing_ && last_tick_) {
    const double wall = std::chrono::duration<double>(now - *last_tick_).count();
    target_ += std::clamp(wall * speed_, 0.0, kMostPerTick);
  }
  last_tick_ = now;
  Tick out;
  out.generation = generation_;
  const LiveFrame frame = run_->advance_to(target_);
  if (frame.estimate) estimate_ = frame.estimate;
  if (run_->ended()) playing_ = false;
  const bool same = frame.t == said_.t && frame.hall.empty() && frame.periods.empty() &&
                    playing_ == said_.playing && speed_ == said_.speed &&
                    generation_ == said_.generation;
  if (!same) {
    out.state = frame_json(frame, playing_, speed_);
    said_ = Said{frame.t, playing_, speed_, generation_};
  }
  if (run_->ended() && !done_sent_) {
    out.done = summary_json(run_->summary());
    done_sent_ = true;
  }
  return out;
}

nlohmann::json LabSession::controls_json() const {
  return {{"t", run_->time()}, {"playing", playing_}, {"speed", speed_}};
}

nlohmann::json LabSession::play(Clock::time_point now) {
  const std::lock_guard lock(mutex_);
  last_seen_ = now;
  if (!run_->ended()) playing_ = true;
  last_tick_ = now;
  return controls_json();
}

nlohmann::json LabSession::pause() {
  const std::lock_guard lock(mutex_);
  playing_ = false;
  return controls_json();
}

nlohmann::json LabSession::step() {
  const std::lock_guard lock(mutex_);
  playing_ = false;
  target_ = std::max(target_, run_->time()) + kFrame;
  return controls_json();
}

nlohmann::json LabSession::reset() {
  const std::lock_guard lock(mutex_);
  run_ = std::make_unique<LiveRun>(prepared_.rig, prepared_.output);
  playing_ = false;
  target_ = 0.0;
  last_tick_.reset();
  done_sent_ = false;
  estimate_.reset();
  ++generation_;
  return controls_json();
}

nlohmann::json LabSession::set_speed(double speed) {
  if (!is_speed(speed))
    throw std::invalid_argument("expected a speed of 1, 0.25 or 0.0625, found " +
                                nlohmann::json(speed).dump());
  const std::lock_guard lock(mutex_);
  speed_ = speed;
  return controls_json();
}

nlohmann::json LabSession::set_name(std::string name) {
  const std::lock_guard lock(mutex_);
  name_ = std::move(name);
  return controls_json();
}

nlohmann::json LabSession::control(const ControlCommand& command, Clock::time_point now) {
  {
    // A control is its page seen, as a stream's tick is.
    const std::lock_guard lock(mutex_);
    last_seen_ = now;
  }
  switch (command.action) {
    case ControlCommand::Action::kPlay:
      return play(now);
    case ControlCommand::Action::kPause:
      return pause();
    case ControlCommand::Action::kStep:
      return step();
    case ControlCommand::Action::kReset:
      return reset();
    case ControlCommand::Action::kSpeed:
      return set_speed(command.speed);
    case ControlCommand::Action::kName:
      return set_name(command.name);
  }
  throw std::logic_error("a control the session does not know");
}

std::string LabSession::name() const {
  const std::lock_guard lock(mutex_);
  return name_;
}

std::optional<std::string> LabSession::file(const std::string& name) {
  const std::lock_guard lock(mutex_);
  if (!run_->ended()) return std::nullopt;
  return run_->file(name);
}

SessionStanding LabSession::standing() const {
  const std::lock_guard lock(mutex_);
  SessionStanding out;
  out.t = run_->time();
  const bool spread = estimate_ && estimate_->has_spread();
  if (run_->ended() && done_sent_) {
    // The summary the page was sent: the run's headline values.
    const RunSummary& s = run_->summary();
    out.state = "done";
    if (s.period) {
      out.period = s.period;
      out.period_from = "sensor";
      if (s.estimator && s.estimator->has_spread()) out.period_err = s.estimator->period_std_error;
    } else if (s.period_trajectory) {
      // A rig without a Hall sensor: the period fitted to the plate's trajectory.
      out.period = s.period_trajectory;
      out.period_err = s.period_trajectory_err;
      out.period_from = "trajectory";
    }
    out.mu_k = s.mu_k_recovered;
    out.mu_k_err = s.mu_k_err_quadrature;
    return out;
  }
  out.state = playing_ ? "playing" : "paused";
  if (estimate_) {
    out.period = estimate_->period;
    out.period_from = "sensor";
    out.mu_k = estimate_->mu_k;
    if (spread) {
      out.period_err = estimate_->period_std_error;
      out.mu_k_err = estimate_->mu_k_err_quadrature;
    }
  }
  return out;
}

Clock::time_point LabSession::last_seen() const {
  const std::lock_guard lock(mutex_);
  return last_seen_;
}

}  // namespace fl::serve
