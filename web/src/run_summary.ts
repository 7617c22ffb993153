// A run's summary as `frictionlab serve` sends it when the run is done: the same object as
// summary.json. Written by tools/generate-fields from the declaration of a run's fields
// (src/lab/run/summary_fields.cpp); a test fails when it is not what the declaration gives.
// generated: run-summary-json
/** A run's summary as the server sends it (summary.json's object; docs/cli.md). */
export interface RunSummaryJson {
  /** the scene's name (its `name:`, else its file's) */
  scene: string;
  /** `world.seed`, which draws the sensor's noise and jitter: `frictionlab run` with a sweep point's overrides (its `set` in sweep.json) and this seed replays it */
  seed: number;
  /** what the trajectory shows: `oscillates`, `clipped`, `stick-slip`, `grows`, `decays`, `sticks`, `tips`, `no restoring force`, `lost` or `numerically failed` (docs/physics.md) */
  regime: string;
  /** [s] when the regime began */
  regime_since_s: number;
  /** why there is no headline period (any regime but `oscillates`, `clipped`, `grows`, `decays`); null when there is a headline period */
  period_withheld: string | null;
  /** the guard's message when one stopped the run; null when no guard stopped the run */
  failure: string | null;
  /** [s] where Ctrl-C or SIGTERM ended the run before its duration; null when the run was not interrupted (left out of summary.json) */
  interrupted_at_s?: number | null;
  /** set when the estimator's period and the trajectory's differ beyond their uncertainties; null when they agree, or one of them is missing */
  estimator_disagreement: string | null;
  /** d ln mu_k / d ln T through the thick formula */
  condition_period: number;
  /** d ln mu_k / d ln l through the thick formula */
  condition_spacing: number;
  /** d ln mu_k / d ln h_c through the thick formula */
  condition_h_c: number;
  /** [s] the headline period: the rig's estimator's mean T from the simulated Hall signal, for a harmonic oscillation only; null when the regime is not harmonic, or the estimator accepted no period */
  period_s: number | null;
  /** [s] dT: the standard deviation of the estimator's periods (the paper's convention); null when the scene has no sensor, or its estimator accepted fewer than two periods */
  period_std_s: number | null;
  /** [s] the standard error of the estimator's mean period; null when the scene has no sensor, or its estimator accepted fewer than two periods */
  period_std_error_s: number | null;
  /** N: the periods the rig's estimator accepted; null when the scene has no sensor */
  periods_used: number | null;
  /** the periods the rig's estimator rejected (an outlier, a broken pulse); null when the scene has no sensor */
  periods_discarded: number | null;
  /** [s] the trajectory's own period, from the crossings of the oscillation's centre; null when the regime is not harmonic */
  period_trajectory_s: number | null;
  /** [s] the standard error of the trajectory's period; null when the regime is not harmonic */
  period_trajectory_err_s: number | null;
  /** [m] the oscillation's centre: the mean of the midpoints of successive turning points over the cycles the period is read from; null when there is no trajectory period */
  oscillation_centre_m: number | null;
  /** [m] the closed form's centre: a tilted rig's x_eq, 0 on a level rig; null when the plate has no restoring force (l <= 2 mu_k h_c) */
  oscillation_centre_theory_m: number | null;
  /** [m/s] skewed axes (`rollers.skew`): the plate's sideways drift along +y over the run's second half; null when the rollers are not skewed */
  drift_speed_m_s: number | null;
  /** [m/s] theory's sideways drift, v_r sin(skew / 2); null when the rollers are not skewed, or their speeds differ or change */
  drift_speed_theory_m_s: number | null;
  /** [rad] `world.tilt` */
  tilt_rad: number;
  /** [s] the paper's period pi sqrt(2 l / (mu_k g)) for the scene's mu_k */
  period_thin_s: number;
  /** [s] the thick plate's period pi sqrt(2 (l - 2 mu_k h_c) / (mu_k g)); null when the plate has no restoring force (l <= 2 mu_k h_c) */
  period_thick_s: number | null;
  /** the headline period against the thin formula's: T / T_thin - 1; null when there is no headline period (period_withheld says why) */
  error_vs_thin: number | null;
  /** the headline period against the thick formula's: T / T_thick - 1; null when there is no headline period (period_withheld says why) */
  error_vs_thick: number | null;
  /** the trajectory's period against the thick formula's; null when there is no trajectory period */
  trajectory_error_vs_thick: number | null;
  /** the scene's mu_k (at the start, for rollers that warm) */
  mu_k_set: number;
  /** mu_k from the headline period through the paper's (thin) formula; from the trajectory's period when `mu_k_source` says so; null when the regime is not harmonic */
  mu_k_recovered: number | null;
  /** where mu_k came from when not from the rig's estimator: `trajectory: the scene has no sensor` or `trajectory: the rig's estimator accepted no period`; null when mu_k came from the rig's estimator (left out of summary.json) */
  mu_k_source?: string | null;
  /** mu_k from the same period through the thick formula with the rig's h_c; null when the regime is not harmonic */
  mu_k_recovered_thick: number | null;
  /** the estimator's own mu_k (thin formula); null when the estimator accepted no period (left out of summary.json) */
  mu_k_estimator?: number | null;
  /** d mu_k, the paper's worst case: mu_k (dl / l + 2 dT / T), dl = 2 mm; null when fewer than two accepted periods (left out of summary.json) */
  mu_k_err_worst?: number | null;
  /** d mu_k in quadrature: mu_k sqrt((dl / l)^2 + (2 dT / T)^2); null when fewer than two accepted periods (left out of summary.json) */
  mu_k_err_quadrature?: number | null;
  /** the semi-implicit Euler step's period error, -(omega dt)^2 / 24; null when the plate has no restoring force (l <= 2 mu_k h_c) */
  predicted_integrator_bias: number | null;
  /** the sensor board's clock runs fast by this fraction (`sensor.clock_error`); null when the clock is exact (left out of summary.json) */
  sensor_clock_error?: number | null;
  /** what the clock's error does to mu_k: 1 / (1 + e)^2 - 1; null when the clock is exact (left out of summary.json) */
  clock_mu_k_bias?: number | null;
  /** [m] the rollers' run-out (`rollers.runout`); null when the rollers are true (left out of summary.json) */
  runout_m?: number | null;
  /** [m] theory's run-out above which the plate hops, at the start amplitude's turning points and the rollers' mean speed (docs/physics.md); null when the rollers are true (left out of summary.json) */
  runout_threshold_m?: number | null;
  /** [m] l, the rollers' spacing */
  spacing_m: number;
  /** [m] the plate's centre of mass above the contact line */
  h_c_m: number;
  /** [kg] the plate with what it carries */
  plate_mass_kg: number;
  /** [rad/s] roller 0's speed (at -l/2; the mean over the run when ramped or driven) */
  roller_speed_rad_s: number;
  /** [rad/s] roller 1's speed (at +l/2; the mean over the run when ramped or driven) */
  roller_speed_1_rad_s: number;
  /** the motor and gears: `motor_speed_rad_s`, `motor_torque_n_m`, `roller_speeds_rad_s`, `gearbox_ratio`, `turning_fraction` (the share of steps in which the motor and both rollers turned), `speed_ratio`, `speed_ratio_error`, `senses_opposite` (these three over the turning steps; null when the train never turned), `load_torque_n_m`; null when the drive is ideal (no motor) */
  drive: Record<string, unknown> | null;
  /** [m/s] the plate's largest speed over the run */
  plate_speed_max_m_s: number;
  /** the rollers' surface speed over the plate's largest speed: infinite (JSON: null) when the plate never moved */
  slip_margin: number;
  /** [m] the first turning point's distance from the centre; null when the run reached no turning point */
  amplitude_start_m: number | null;
  /** [m] the last turning point's distance from the centre; null when the run reached no turning point */
  amplitude_end_m: number | null;
  /** the amplitude's relative change per period; null when the run reached fewer than two turning points */
  amplitude_drift_per_period: number | null;
  /** [s] `clipped`: when the first stick began; null when the regime is not `clipped` (left out of summary.json) */
  clip_time_s?: number | null;
  /** [m] `clipped`: the amplitude before the first stick; null when the regime is not `clipped` (left out of summary.json) */
  amplitude_before_clip_m?: number | null;
  /** [m] `clipped`: the settled amplitude after the sticks; null when the regime is not `clipped` (left out of summary.json) */
  amplitude_clipped_m?: number | null;
  /** [s] `stick-slip`: the cycle's period; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_slip_period_s?: number | null;
  /** [m] `stick-slip`: the cycle's amplitude; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_slip_amplitude_m?: number | null;
  /** [s] `stick-slip`: one stick phase; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_duration_s?: number | null;
  /** [1/s] `grows`, `decays`: d ln A / dt measured at the turning points; null when the regime is neither (left out of summary.json) */
  growth_rate_per_s?: number | null;
  /** [s] `grows`, `decays`: 1 / |growth rate|; null when the regime is neither (left out of summary.json) */
  e_folding_time_s?: number | null;
  /** how many times the plate left a roller (a tube off its shaft); null when the plate never left (left out of summary.json) */
  jumps?: number | null;
  /** [s] when the plate first left a roller; null when the plate never left (left out of summary.json) */
  first_jump_time_s?: number | null;
  /** [s] the longest time off a roller; null when the plate never left (left out of summary.json) */
  longest_jump_s?: number | null;
  /** [m] the largest gap between the plate's bottom and a roller; null when the plate never left (left out of summary.json) */
  highest_jump_m?: number | null;
  /** the regime the friction law's closed forms give for the scene (docs/friction-laws.md); null when the regime is not `clipped`, `stick-slip`, `grows` or `decays` (left out of summary.json) */
  regime_theory?: string | null;
  /** [m] theory's clipped amplitude, v_r / Omega; null when the regime is not `clipped` (left out of summary.json) */
  amplitude_clipped_theory_m?: number | null;
  /** [s] the stick-slip cycle's period, closed form; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_slip_period_theory_s?: number | null;
  /** [m] the stick-slip cycle's amplitude, closed form; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_slip_amplitude_theory_m?: number | null;
  /** [s] one stick phase, closed form; null when the regime is not `stick-slip` (left out of summary.json) */
  stick_duration_theory_s?: number | null;
  /** [1/s] theory's growth rate, averaged over the start's cycle; null when the regime is neither `grows` nor `decays` (left out of summary.json) */
  growth_rate_theory_per_s?: number | null;
  /** rollers warming (`friction.warming`): `start_temperature_k`, `room_temperature_k`, `time_constant_s`, `hold_s`, `mu_k_start`, `mu_k_room`, `end_temperature_k`, `mu_k_end`, `mu_k_cold_paper_formula` (the paper's formula on rollers that stay cold), and the windows `first_10_periods`, `first_30_s`, `whole_run`, each `{periods, period_s, mu_k}` from the estimator's accepted periods (null when a window holds none); null when the rollers do not warm (left out of summary.json) */
  warming?: Record<string, unknown> | null;
  /** what the paper measured for the scene's material: `material`, `period_s`, `period_err_s`, `mu_k`, `mu_k_err`; null when the scene's mu_k is not a row of the paper's Table I (left out of summary.json) */
  paper?: Record<string, unknown> | null;
  /** [N] the smallest normal force on the plate at a roller over the run */
  min_normal_force_n: number;
  /** [m] the plate's deepest penetration into a roller over the run */
  max_penetration_m: number;
  /** [s] the physics step (`world.time_step`, or the one an accuracy chose) */
  time_step_s: number;
  /** the contact solver's iterations the run ended with */
  solver_iterations: number;
  /** from which iterations to which the run raised them, and why; null when the contact solver converged at the scene's (left out of summary.json) */
  solver_iterations_raised?: string | null;
  /** [s] simulated time */
  duration_s: number;
  /** physics steps taken */
  steps: number;
  /** what showed the regime (which force, which speed) */
  regime_evidence: string;
}
// end generated
