#include "lab/experiment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/analytic_model.hpp"
#include "core/oscillation_tracker.hpp"
#include "lab/hall_estimator.hpp"

namespace fl {
namespace {

PlatePose pose_of(double t, const PlateState& s) {
  return PlatePose{t, s.x, s.z, s.pitch, s.vx, s.vz, s.pitch_rate};
}

}  // namespace

RunSummary run_experiment(const Scene& scene, const RunOptions& options, RunRecording* recording) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunSummary out;
  out.scene = scene.name;
  out.seed = scene.world.seed;
  out.spacing = scene.rollers.spacing;
  out.mu_k_set = scene.friction.mu_k;
  out.time_step = scene.world.time_step;
  out.solver_iterations = scene.world.solver_iterations;
  out.roller_speed = scene.rollers.speed;
  if (scene.friction.from_paper) {
    out.paper_material = scene.friction.paper_material;
    out.paper_period = scene.friction.paper_period;
    out.paper_mu_k = scene.friction.paper_mu_k;
  }

  RigWorld world(scene);
  out.h_c = world.plate_h_c();
  out.plate_mass = world.plate_mass();
  const double g = scene.world.gravity;
  out.period_thin = period_thin(out.spacing, out.mu_k_set, g);
  if (has_restoring_force(out.spacing, out.mu_k_set, out.h_c)) {
    out.period_thick = period_thick(out.spacing, out.mu_k_set, out.h_c, g);
    const double omega_dt = 2.0 * std::numbers::pi / *out.period_thick * out.time_step;
    out.predicted_integrator_bias = -omega_dt * omega_dt / 24.0;
  }

  // Only what the scene names: no sensor, no Hall signal and no estimator.
  std::optional<HallSignal> hall;
  std::optional<HallEstimator> estimator;
  if (scene.sensor && !scene.magnets.empty()) {
    hall.emplace(scene);
    estimator.emplace(scene.rollers.spacing, g);
  }
  const auto on_sample = [&](const HallSample& sample) {
    estimator->add(sample);
    if (options.record_hall && recording != nullptr) recording->hall.push_back(sample);
  };

  OscillationTracker tracker;
  PlateState state = world.plate();
  tracker.add(0.0, state.x, state.vx);
  if (options.record_trajectory && recording != nullptr)
    recording->trajectory.push_back({0.0, state, world.contacts()});

  const long long steps = std::llround(scene.world.duration / scene.world.time_step);
  out.min_normal_force = std::numeric_limits<double>::infinity();
  double t_previous = 0.0;
  PlateState previous = state;
  const double half_length = 0.5 * scene.plate.length;
  bool tipped = false;
  double tipped_at = 0.0;
  bool lost = false;
  double lost_at = 0.0;
  for (long long i = 0; i < steps; ++i) {
    world.step();
    const double t = world.time();
    state = world.plate();
    const auto contacts = world.contacts();
    tracker.add(t, state.x, state.vx);
    if (hall) hall->sample_between(pose_of(t_previous, previous), pose_of(t, state), on_sample);
    if (options.record_trajectory && recording != nullptr)
      recording->trajectory.push_back({t, state, contacts});
    out.plate_speed_max = std::max(out.plate_speed_max, std::fabs(state.vx));
    for (const RollerContact& c : contacts) {
      out.min_normal_force = std::min(out.min_normal_force, c.normal_force);
      out.max_penetration = std::max(out.max_penetration, c.penetration);
      if (!tipped && c.normal_force <= 0.0) {
        tipped = true;
        tipped_at = t;
      }
    }
    if (!lost && (std::fabs(state.x) > half_length || state.z < -scene.rollers.radius)) {
      lost = true;
      lost_at = t;
      break;
    }
    previous = state;
    t_previous = t;
  }
  out.steps = world.steps();
  out.duration = world.time();

  if (const auto p = tracker.period()) {
    out.period_trajectory = p->slope;
    out.period_trajectory_err = p->slope_std_error;
  }
  if (!tracker.turning_amplitudes().empty()) {
    out.amplitude_start = tracker.turning_amplitudes().front();
    out.amplitude_end = tracker.turning_amplitudes().back();
  }
  out.amplitude_drift_per_period = tracker.amplitude_drift_per_period();
  if (estimator) out.estimator = estimator->report();
  const double surface_speed = scene.rollers.speed * scene.rollers.radius;
  out.slip_margin = out.plate_speed_max > 0.0 ? surface_speed / out.plate_speed_max
                                              : std::numeric_limits<double>::infinity();

  // The regime, from the run itself (issue 8 refines this diagnosis).
  if (!has_restoring_force(out.spacing, out.mu_k_set, out.h_c) ||
      scene.rollers.sense == RollerSense::kOutward) {
    out.regime = "no restoring force";
    out.regime_reason = "l <= 2 mu_k h_c or rollers turning outward";
  } else if (lost) {
    out.regime = "lost";
    out.regime_reason = "the plate left the rollers at t = " + std::to_string(lost_at) + " s";
  } else if (tipped) {
    out.regime = "tips";
    out.regime_reason = "a normal force reached zero at t = " + std::to_string(tipped_at) + " s";
  } else if (out.slip_margin <= 1.0) {
    out.regime = "sticks";
    out.regime_reason = "the plate reached a roller's surface speed (slip margin <= 1)";
  } else {
    out.regime = "oscillates";
    out.regime_reason = "both rollers slip throughout";
  }

  // mu_k as the rig would report it: from the estimator's period (the trajectory's when the
  // scene has no sensor), only for a harmonic oscillation.
  const double period_for_mu = out.estimator && out.estimator->periods_used > 0
                                   ? out.estimator->period
                                   : out.period_trajectory.value_or(0.0);
  if (out.regime == "oscillates" && period_for_mu > 0.0) {
    out.mu_k_recovered = mu_k_from_period_thin(period_for_mu, out.spacing, g);
    out.mu_k_recovered_thick = mu_k_from_period_thick(period_for_mu, out.spacing, out.h_c, g);
  }

  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  out.real_time_factor = out.duration / out.wall_s;
  out.steps_per_second = static_cast<double>(out.steps) / out.wall_s;
  return out;
}

}  // namespace fl
