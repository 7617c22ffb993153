// One run of a scene: builds the world from exactly what the scene names, steps it, streams the
// simulated Hall samples into the rig's period estimator, follows the trajectory's own period,
// and summarises the run against the analytic model.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/rig_world.hpp"
#include "scene/scene.hpp"
#include "sensor/hall_signal.hpp"

namespace fl {

struct TrajectoryRow {
  double t = 0.0;  // s
  PlateState plate;
  std::array<RollerContact, 2> rollers;
};

// The period the rig's estimator measured from the simulated Hall signal.
struct EstimatorReport {
  int periods_used = 0;
  int periods_discarded = 0;
  int pulses = 0;
  double period = 0.0;            // s, mean
  double period_std = 0.0;        // s, standard deviation of the periods
  double period_std_error = 0.0;  // s, of the mean
  double mu_k = 0.0;              // from the mean period, thin formula (the paper's)
  double mu_k_err_worst = 0.0;
  double mu_k_err_quadrature = 0.0;
};

// The motor and gears over the run (scenes with a drive).
struct DriveReport {
  double motor_speed = 0.0;               // rad/s, mean, in the motor's driving sense
  double motor_torque = 0.0;              // N m, mean
  std::array<double, 2> roller_speeds{};  // rad/s about +y, mean
  double gearbox_ratio = 0.0;             // the design's speed-up, from the tooth counts
  double speed_ratio = 0.0;               // |roller 0| / |motor|, mean
  double speed_ratio_error = 0.0;         // largest |ratio / design - 1| over the steps
  bool senses_opposite = true;            // the rollers turned opposite ways at every step
  double load_torque = 0.0;  // N m, mean torque the plate's friction takes from the rollers
};

struct RunSummary {
  std::string scene;
  std::uint64_t seed = 0;
  double spacing = 0.0;  // m
  double mu_k_set = 0.0;
  double h_c = 0.0;         // m
  double plate_mass = 0.0;  // kg
  double time_step = 0.0;   // s
  int solver_iterations = 0;
  double duration = 0.0;  // s simulated
  long long steps = 0;
  std::string paper_material;            // Table I key, when the scene took mu_k from the paper
  std::optional<Measured> paper_period;  // what the paper measured for it [s]
  std::optional<Measured> paper_mu_k;

  // The analytic model for the scene's true mu_k and h_c.
  double period_thin = 0.0;                         // s
  std::optional<double> period_thick;               // s; none without a restoring force
  std::optional<double> predicted_integrator_bias;  // relative, -(omega dt)^2 / 24

  // The trajectory's own period (crossings of x = 0), and the estimator's from the Hall signal.
  std::optional<double> period_trajectory;      // s
  std::optional<double> period_trajectory_err;  // s, standard error of the fit
  std::optional<EstimatorReport> estimator;
  std::optional<double> mu_k_recovered;        // from the estimator's period, thin formula
  std::optional<double> mu_k_recovered_thick;  // the same through the thick formula with h_c

  double amplitude_start = 0.0;                      // m, first turning point
  double amplitude_end = 0.0;                        // m, last turning point
  std::optional<double> amplitude_drift_per_period;  // relative
  double roller_speed = 0.0;                         // rad/s (mean |roller 0| when driven)
  std::optional<DriveReport> drive;
  double plate_speed_max = 0.0;   // m/s
  double slip_margin = 0.0;       // roller surface speed / plate's largest speed
  double min_normal_force = 0.0;  // N, over the run
  double max_penetration = 0.0;   // m
  // The regime diagnosed from the run (src/lab/regime_monitor.hpp), when it began and why; a
  // period is reported only for "oscillates", otherwise period_withheld says why not.
  std::string regime;
  double regime_since = 0.0;  // s
  std::string regime_evidence;
  std::string period_withheld;
  // A guard stopped the run (numerical failure, or the plate left the rig): exit status 3.
  std::optional<std::string> failure;
  // The estimator's period against the trajectory's own: a disagreement beyond both
  // uncertainties is reported here.
  std::optional<std::string> estimator_disagreement;
  // How errors in T and l carry into mu_k through the thick formula for this h_c.
  double condition_period = 0.0;
  double condition_spacing = 0.0;
  double condition_h_c = 0.0;

  double wall_s = 0.0;
  double real_time_factor = 0.0;
  double steps_per_second = 0.0;
};

struct RunRecording {
  std::vector<TrajectoryRow> trajectory;  // every step, when asked for
  std::vector<HallSample> hall;           // every sample, when asked for
};

class HallEstimator;

// What a run looks like after each step, for an observer (the video renderer): everything needed
// to draw the rig and its overlays at any instant between two steps.
struct StepView {
  double t = 0.0;  // s
  PlateState plate;
  std::array<double, 2> roller_angles{};     // rad about +y since the start
  std::array<double, 2> roller_speeds{};     // rad/s about +y
  std::optional<DriveState> drive;           // the motor and gears, when the scene has a drive
  std::vector<ShaftState> shafts;            // the drive layout's shafts (scene/drive_layout.hpp)
  std::vector<HallSample> new_samples;       // the Hall samples taken during this step
  const HallEstimator* estimator = nullptr;  // the rig's estimator, live (null without a sensor)
};

struct RunOptions {
  bool record_trajectory = false;
  bool record_hall = false;
  // Called after every step (and once at t = 0) when set.
  std::function<void(const StepView&)> observer;
};

RunSummary run_experiment(const Scene& scene, const RunOptions& options,
                          RunRecording* recording = nullptr);

}  // namespace fl
