// What one run found, as one typed value: the regime (the same enum theory uses), the headline
// period and mu_k decided by the run (lab/run/experiment.cpp) with their source, the estimator's
// and the trajectory's periods, the analytic model's, the drive's figures and the run's cost.
// Compare, sweeps, stability and the outputs read this struct; its JSON and CSV forms come from one
// table of fields (lab/run/summary_fields.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "core/regime.hpp"
#include "core/units.hpp"
#include "lab/run/warming_report.hpp"

namespace fl {

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

  // A spread (dT, the standard error, d mu_k) needs two accepted periods: below that it is not
  // measured, and every output gives it as null, never 0. The one place that says so.
  bool has_spread() const { return periods_used >= 2; }
};

// The motor and gears over the run (scenes with a drive).
struct DriveReport {
  double motor_speed = 0.0;               // rad/s, mean, in the motor's driving sense
  double motor_torque = 0.0;              // N m, mean
  std::array<double, 2> roller_speeds{};  // rad/s about +y, mean
  double gearbox_ratio = 0.0;             // the design's speed-up, from the tooth counts
  // The share of the steps in which the motor and both rollers turned; the three below are
  // measured over those steps only, and null when there were none (a train stalled from the start
  // or a motor at zero duty has no ratio to measure).
  double turning_fraction = 0.0;
  std::optional<double> speed_ratio;        // |roller 0| / |motor|, mean
  std::optional<double> speed_ratio_error;  // largest |ratio / design - 1|
  std::optional<bool> senses_opposite;      // the rollers turned opposite ways at every such step
  double load_torque = 0.0;  // N m, mean torque the plate's friction takes from the rollers
};

// Where the run's mu_k comes from: the rig's estimator on the Hall signal, or (for a scene
// without a sensor) the trajectory's own period.
enum class PeriodSource { kHallEstimator, kTrajectory };

struct RunSummary {
  std::string scene;
  std::uint64_t seed = 0;
  double spacing = 0.0;  // m
  double mu_k_set = 0.0;
  double h_c = 0.0;          // m
  double plate_mass = 0.0;   // kg
  double gravity = 0.0;      // m/s^2
  double temperature = 0.0;  // K, of the rollers (friction.temperature)
  // The sensor board's clock error e (sensor.clock_error), when the scene sets one: the estimator's
  // periods read 1 + e times the true ones, its mu_k (1 + e)^-2 times.
  std::optional<double> clock_error;
  // Rollers off their shafts (rollers.runout), when the scene sets them: the run-out [m], and the
  // run-out above which theory has the plate hop at its start amplitude's turning points, at the
  // rollers' mean speed over the run (core/runout.hpp) [m].
  std::optional<double> runout;
  std::optional<double> runout_threshold;
  // Rollers warming over the run (friction.warming): their temperature and mu_k, and the mu_k a
  // student computes from the estimator's periods over the first 10, the first 30 s, the run.
  std::optional<WarmingReport> warming;
  double time_step = 0.0;     // s
  int solver_iterations = 0;  // the iterations the run ended with
  // When the run raised them (the scene's did not converge): from what, to what, and why.
  std::optional<std::string> solver_iterations_raised;
  double duration = 0.0;  // s simulated
  long long steps = 0;
  std::string paper_material;            // Table I key, when the scene took mu_k from the paper
  std::optional<Measured> paper_period;  // what the paper measured for it [s]
  std::optional<Measured> paper_mu_k;

  // The analytic model for the scene's true mu_k and h_c (from the compiled rig).
  double period_thin = 0.0;                         // s
  std::optional<double> period_thick;               // s; none without a restoring force
  std::optional<double> predicted_integrator_bias;  // relative, -(omega dt)^2 / 24
  std::optional<double> slip_threshold;             // rad/s, roller speed for full slip

  // The regime diagnosed from the run (lab/run/regime_monitor.hpp), when it began and why.
  Regime regime = Regime::kOscillates;
  double regime_since = 0.0;  // s
  std::string regime_evidence;
  // What the trajectory showed in numbers (lab/run/motion_diagnosis.hpp); null where the regime has
  // none (a full-slip oscillation has none of them).
  std::optional<double> clip_time;              // s, clipped: when the first stick began
  std::optional<double> amplitude_before_clip;  // m, clipped
  std::optional<double> amplitude_clipped;      // m, clipped: the steady amplitude after it
  std::optional<double> stick_slip_period;      // s, stick-slip: the cycle's period
  std::optional<double> stick_slip_amplitude;   // m, stick-slip
  std::optional<double> stick_duration;         // s, stick-slip: one stick phase
  std::optional<double> growth_rate;            // 1/s, grows or decays: d ln A / dt, measured
  std::optional<double> e_folding_time;         // s, grows or decays: 1 / |growth_rate|
  // Jumps: the plate left a roller and came back, again and again at the same point of the
  // roller's turn (rollers off their shafts); null when it never did.
  std::optional<int> jumps;
  std::optional<double> first_jump_time;  // s
  std::optional<double> longest_jump;     // s
  std::optional<double> highest_jump;     // m, the largest gap between the plate and a roller
  // The same numbers from the friction law's closed forms (lab/run/regime_theory.hpp), where the
  // run has them to be held against.
  std::optional<Regime> regime_theory;                // when the regime has numbers above
  std::optional<double> amplitude_clipped_theory;     // m, v_r / Omega
  std::optional<double> stick_slip_period_theory;     // s
  std::optional<double> stick_slip_amplitude_theory;  // m
  std::optional<double> stick_duration_theory;        // s
  std::optional<double> growth_rate_theory;           // 1/s, averaged over the start's cycle

  // The headline, decided by the run: a period only for a harmonic oscillation. `period` is the
  // rig's estimator's mean period from the Hall signal; mu_k comes from it, or from the
  // trajectory's period when the scene has no sensor (mu_k_source). When there is no period,
  // period_withheld says why.
  std::optional<double> period;                // s
  std::optional<double> mu_k_recovered;        // thin formula (the paper's)
  std::optional<double> mu_k_recovered_thick;  // thick formula with the rig's h_c
  std::optional<PeriodSource> mu_k_source;
  std::optional<std::string> period_withheld;
  // The estimator's own mu_k (thin formula) and its uncertainties, for a harmonic oscillation.
  std::optional<double> mu_k_estimator;
  std::optional<double> mu_k_err_worst;
  std::optional<double> mu_k_err_quadrature;

  // The estimator's report (scenes with a sensor and magnets), whatever the regime.
  std::optional<EstimatorReport> estimator;
  // The trajectory's own period (crossings of the oscillation's centre), for a harmonic
  // oscillation only.
  std::optional<double> period_trajectory;      // s
  std::optional<double> period_trajectory_err;  // s, standard error of the fit
  // m, the oscillation's centre: the mean of the midpoints of successive turning points over the
  // cycles the period is read from (with it); and where theory puts it (a tilted rig's x_eq, 0 on
  // a level one; null without a restoring force).
  std::optional<double> oscillation_centre;
  std::optional<double> oscillation_centre_theory;
  // Skewed axes (rollers.skew): the plate's sideways drift along +y [m/s], fitted over the run's
  // second half, and theory's v_r sin(skew / 2); null without skew (the plate cannot drift) or,
  // for theory, when the two rollers' surface speeds differ or change.
  std::optional<double> drift_speed;
  std::optional<double> drift_speed_theory;
  double tilt = 0.0;  // rad, world.tilt
  // The estimator's period against the trajectory's: a disagreement beyond both uncertainties.
  std::optional<std::string> estimator_disagreement;

  // m, the first and the last turning point; null for a run too short to reach one.
  std::optional<double> amplitude_start;
  std::optional<double> amplitude_end;
  std::optional<double> amplitude_drift_per_period;  // relative
  double roller_speed = 0.0;    // rad/s, roller 0's (mean |roller 0| when driven or ramped)
  double roller_speed_1 = 0.0;  // rad/s, roller 1's (mean |roller 1| when driven or ramped)
  std::optional<DriveReport> drive;
  double plate_speed_max = 0.0;   // m/s
  double slip_margin = 0.0;       // roller surface speed / plate's largest speed
  double min_normal_force = 0.0;  // N, over the run
  double max_penetration = 0.0;   // m
  // A guard stopped the run (numerical failure, or the plate left the rig): exit status 3.
  std::optional<std::string> failure;
  // s: the run was asked to stop (an interrupt) and ended here, before its duration.
  std::optional<double> interrupted_at;
  // How errors in T and l carry into mu_k through the thick formula for this h_c.
  double condition_period = 0.0;
  double condition_spacing = 0.0;
  double condition_h_c = 0.0;

  double wall_s = 0.0;
  double real_time_factor = 0.0;
  double steps_per_second = 0.0;

  // An oscillation whose period the paper's formula reads (core/regime.hpp).
  bool harmonic() const { return regime_is_harmonic(regime); }
  // The run gave no trustworthy result: a guard stopped it, or its steps did not resolve the
  // physics (regime "numerically failed"). A run exits 3 for it, a sweep point is "failed".
  bool failed() const { return failure.has_value() || regime == Regime::kNumericallyFailed; }
};

}  // namespace fl
