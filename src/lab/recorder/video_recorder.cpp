// The recorder in the executable: it checks the request, opens the video module and hands it
// each step as plain values. No renderer here (src/lab/CMakeLists.txt keeps fl_lab off
// fl_render).
#include "lab/recorder/video_recorder.hpp"

#include <fmt/format.h>

#include "lab/run/hall_estimator.hpp"
#include "lab/video/video_module.hpp"

namespace fl {
namespace {

// The step as the module takes it. `out`'s vectors are reused from step to step.
void copy_step(const StepView& view, VideoStep& out, double& next_regime_t) {
  out.t = view.t;
  out.plate_x = view.plate.x;
  out.plate_y = view.plate.y;
  out.plate_z = view.plate.z;
  out.pitch = view.plate.pitch;
  out.yaw = view.plate.yaw;
  out.plate_vx = view.plate.vx;
  for (std::size_t k = 0; k < 2; ++k) {
    const RollerContact& c = view.contacts[k];
    out.contacts[k] =
        VideoContact{c.touching, c.normal_force, c.friction_force, c.point_x, c.point_z};
  }
  out.shaft_angles.clear();
  out.shaft_speeds.clear();
  if (!view.shafts.empty()) {
    for (const ShaftState& s : view.shafts) {
      out.shaft_angles.push_back(s.angle);
      out.shaft_speeds.push_back(s.speed);
    }
  } else {
    out.shaft_angles.assign(view.roller_angles.begin(), view.roller_angles.end());
    out.shaft_speeds.assign(view.roller_speeds.begin(), view.roller_speeds.end());
  }
  out.motor_speed.reset();
  if (view.drive) out.motor_speed = view.drive->motor_speed;
  out.roller_speed = view.roller_speeds[0];
  // The diagnosis so far, read every 10 ms of simulated time (a frame's worth at most).
  if (view.monitor != nullptr && (out.regime.empty() || view.t >= next_regime_t)) {
    out.regime = regime_so_far(view.monitor->finding(std::nullopt));
    next_regime_t = view.t + 0.01;
  }
  out.new_samples.clear();
  for (const HallSample& sample : view.new_samples)
    out.new_samples.push_back({sample.t_us * 1e-6, static_cast<double>(sample.adc)});
  if (view.estimator == nullptr) {
    out.estimate.reset();
    return;
  }
  const EstimatorReport r = view.estimator->report();
  VideoEstimate& e = out.estimate ? *out.estimate : out.estimate.emplace();
  e.pulses = r.pulses;
  e.periods_used = r.periods_used;
  e.period = r.period;
  e.period_std = r.period_std;
  e.mu_k = r.mu_k;
  e.mu_k_err_worst = r.mu_k_err_worst;
  e.pulse_times = view.estimator->pulse_times();
  e.learning_pulse_times = view.estimator->learning_pulse_times();
  e.signal_learned = view.estimator->signal_learned();
  e.geometry_known = view.estimator->geometry_known();
  e.provisional_periods = view.estimator->provisional_periods();
  e.periods_discarded = r.periods_discarded;
  e.discarded.clear();
  e.turning_points.clear();
  for (const EstimatedPeriod& p : view.estimator->judged_periods()) {
    if (p.status != fl_estimator::kAccepted) e.discarded.push_back({p.start, p.end});
    // Successive periods share their turning point.
    if (e.turning_points.empty() || e.turning_points.back() < p.start - 1e-9)
      e.turning_points.push_back(p.start);
    e.turning_points.push_back(p.end);
  }
}

}  // namespace

struct VideoRecorder::Impl {
  std::unique_ptr<VideoEngine> engine;
  VideoStep step;
  double next_regime_t = 0.0;  // s, when the diagnosis is read again
};

VideoRecorder::VideoRecorder(std::shared_ptr<const CompiledRig> rig, const VideoDesc& video,
                             const VideoRequest& request)
    : impl_(std::make_unique<Impl>()) {
  impl_->engine = load_video_module().make_engine(std::move(rig), video, request);
}

VideoRecorder::~VideoRecorder() = default;

void VideoRecorder::observe(const StepView& view) {
  copy_step(view, impl_->step, impl_->next_regime_t);
  impl_->engine->observe(impl_->step);
}

VideoReport VideoRecorder::finish(const VideoEnding& ending) {
  return impl_->engine->finish(ending);
}

std::string VideoRecorder::note() const {
  return impl_->engine->note();
}

}  // namespace fl
