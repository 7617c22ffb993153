#include "lab/run/experiment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/oscillation_tracker.hpp"
#include "core/runout.hpp"
#include "lab/run/hall_estimator.hpp"
#include "lab/run/regime_monitor.hpp"
#include "lab/run/regime_theory.hpp"
#include "lab/run/run_monitors.hpp"
#include "lab/run/solver_convergence.hpp"
#include "lab/run/warming_report.hpp"

namespace fl {
namespace {

// The estimator's mean period against the trajectory's: they measure the same motion, so they
// must agree within the estimator's standard error (three of them) plus 0.05 % for the
// estimator's single-precision arithmetic and its pulse timing.
// The estimator's period against the trajectory's, as the board's clock (running fast by
// `clock_error`) reads the latter.
std::optional<std::string> cross_check(const EstimatorReport& e, double trajectory_period,
                                       double clock_error) {
  if (e.periods_used == 0) return std::nullopt;
  const double read = trajectory_period * (1.0 + clock_error);
  const double bound = 3.0 * e.period_std_error + 5e-4 * read;
  const double difference = e.period - read;
  if (std::fabs(difference) <= bound) return std::nullopt;
  return fmt::format(
      "the estimator's period {:.6f} s differs from the trajectory's {:.6f} s{} by "
      "{:+.4f} %, more than its uncertainty allows ({:.4f} %)",
      e.period, read, clock_error != 0.0 ? " (as the board's clock reads it)" : "",
      100.0 * difference / read, 100.0 * bound / read);
}

// The friction law's closed forms for a regime that has numbers (a clip, a stick-slip cycle, a
// growth rate), to be held against the run's.
void theory_numbers(const CompiledRig& rig, RunSummary& out) {
  const TheoryRegime theory = regime_from_theory(rig);
  out.regime_theory = theory.regime;
  if (!theory.prediction) return;
  const FrictionRegimePrediction& p = *theory.prediction;
  if (p.cycle) {
    if (p.cycle->clipped) {
      out.amplitude_clipped_theory = p.cycle->amplitude;
    } else {
      out.stick_slip_period_theory = p.cycle->period;
      out.stick_slip_amplitude_theory = p.cycle->amplitude;
      out.stick_duration_theory = p.cycle->stick_duration;
    }
  }
  if (p.regime == Regime::kGrows || p.regime == Regime::kDecays)
    out.growth_rate_theory = p.growth_rate;
}

// What the summary says of the rig before it runs: the set-up, the analytic model's numbers.
void rig_figures(const CompiledRig& rig, RunSummary& out) {
  out.scene = rig.name;
  out.seed = rig.world.seed;
  out.spacing = rig.rollers.spacing;
  out.mu_k_set = rig.friction.mu_k;
  out.h_c = rig.plate.h_c;
  out.plate_mass = rig.plate.mass;
  out.gravity = rig.world.gravity;
  out.tilt = rig.world.tilt;
  out.oscillation_centre_theory = rig.oscillation_centre;
  out.temperature = rig.friction_source.temperature;
  out.time_step = rig.world.time_step;
  if (rig.sensor && rig.sensor->clock_error != 0.0) out.clock_error = rig.sensor->clock_error;
  out.solver_iterations = rig.world.solver_iterations;
  out.roller_speed = rig.rollers.speed;
  out.roller_speed_1 = rig.rollers.speed_roller_1.value_or(rig.rollers.speed);
  if (const FrictionSource& source = rig.friction_source; source.paper_material) {
    out.paper_material = *source.paper_material;
    out.paper_period = source.paper_period;
    out.paper_mu_k = source.paper_mu_k;
  }
  out.period_thin = rig.period_thin;
  out.period_thick = rig.period_thick;
  out.predicted_integrator_bias = rig.integrator_bias;
  out.slip_threshold = rig.slip_threshold;
  if (rig.conditioning) {
    out.condition_period = rig.conditioning->condition_period;
    out.condition_spacing = rig.conditioning->condition_spacing;
    out.condition_h_c = rig.conditioning->condition_h_c;
  }
}

// The regime the run's monitor found, with what the trajectory showed in numbers and the friction
// law's closed forms for them; returns the time from which the motion is harmonic (after a
// clip's last stick, or where a growth or decay began).
double add_regime(const CompiledRig& rig, const RegimeFinding& finding, RunSummary& out,
                  RunRecording* recording) {
  out.regime = finding.regime;
  out.regime_since = finding.since;
  out.regime_evidence = finding.evidence;
  if (finding.jumps > 0) {
    out.jumps = finding.jumps;
    out.first_jump_time = finding.first_jump;
    out.longest_jump = finding.longest_jump;
    out.highest_jump = finding.highest_jump;
    if (recording != nullptr) recording->jumps = finding.jump_list;
  }
  double harmonic_since = 0.0;
  if (finding.motion && finding.motion->regime == finding.regime) {
    const MotionFinding& m = *finding.motion;
    if (m.regime == Regime::kClipped) {
      out.clip_time = m.clip_time;
      out.amplitude_before_clip = m.amplitude_before;
      out.amplitude_clipped = m.amplitude_after;
      harmonic_since = m.slipping_since.value_or(0.0);
    } else if (m.regime == Regime::kStickSlip) {
      out.stick_slip_period = m.cycle_period;
      out.stick_slip_amplitude = m.cycle_amplitude;
      out.stick_duration = m.stick_duration;
    } else if (m.regime == Regime::kGrows || m.regime == Regime::kDecays) {
      out.growth_rate = m.growth_rate;
      if (m.growth_rate && *m.growth_rate != 0.0)
        out.e_folding_time = 1.0 / std::fabs(*m.growth_rate);
      harmonic_since = m.since;
    }
    if (m.regime == Regime::kClipped || m.regime == Regime::kStickSlip ||
        m.regime == Regime::kGrows || m.regime == Regime::kDecays)
      theory_numbers(rig, out);
  }
  return harmonic_since;
}

// The headline: a period only for a harmonic oscillation, where the paper's model holds; mu_k as
// the rig would report it, from the estimator's period, or from the trajectory's (said so) when
// the scene has no sensor or its estimator accepted none.
void decide_headline(RunSummary& out) {
  const double g = out.gravity;
  if (!out.harmonic()) {
    out.period_trajectory.reset();
    out.period_trajectory_err.reset();
    out.oscillation_centre.reset();
    out.period_withheld = fmt::format(
        "no period: the regime is '{}', not a harmonic oscillation, so the paper's model does "
        "not hold",
        regime_name(out.regime));
  } else {
    // mu_k as the rig would report it: from the estimator's period; from the trajectory's when
    // the scene has no sensor or its estimator accepted no period.
    // The estimator's mu_k from one accepted period on; its uncertainty, from the periods'
    // spread, from two.
    if (out.estimator && out.estimator->periods_used > 0) out.mu_k_estimator = out.estimator->mu_k;
    if (out.estimator && out.estimator->has_spread()) {
      out.mu_k_err_worst = out.estimator->mu_k_err_worst;
      out.mu_k_err_quadrature = out.estimator->mu_k_err_quadrature;
    }
    std::optional<double> period_for_mu = out.period_trajectory;
    out.mu_k_source = PeriodSource::kTrajectory;
    if (out.estimator && out.estimator->periods_used > 0) {
      out.period = out.estimator->period;
      period_for_mu = out.period;
      out.mu_k_source = PeriodSource::kHallEstimator;
    } else if (out.estimator) {
      out.period_withheld = fmt::format(
          "no period: {}{}",
          out.estimator->pulses == 0
              ? std::string("the Hall sensor saw no pulse: the magnets never came near it (check "
                            "sensor.position against where the magnets swing)")
              : fmt::format("the rig's estimator accepted none from {} Hall pulse(s) (the pulses "
                            "too weak or unlike each other, or the run too short)",
                            out.estimator->pulses),
          out.period_trajectory ? fmt::format("; mu_k comes from the trajectory's period {:.6f} s",
                                              *out.period_trajectory)
                                : std::string());
    } else if (!out.period_trajectory) {
      out.period_withheld =
          "no period: fewer than two turning points were measured; simulate longer";
    }
    if (period_for_mu && *period_for_mu > 0.0) {
      out.mu_k_recovered = mu_k_from_period_thin(*period_for_mu, out.spacing, g);
      out.mu_k_recovered_thick = mu_k_from_period_thick(*period_for_mu, out.spacing, out.h_c, g);
    } else {
      out.mu_k_source.reset();
    }
  }
}

}  // namespace

struct RunLoop::Impl {
  Impl(const CompiledRig& r, const RunOptions& o, RunRecording* rec)
      : rig(r), options(o), recording(rec), world(r), regime(r), convergence(r) {
    if (rec != nullptr) memory.emplace(*rec);
    if (o.stream != nullptr)
      keep = o.stream;
    else if (memory)
      keep = &*memory;
  }

  const CompiledRig& rig;
  const RunOptions& options;
  RunRecording* recording;
  // Where the trajectory and the Hall samples asked for go: the options' stream, else the
  // recording.
  std::optional<RecordingSink> memory;
  RecordSink* keep = nullptr;
  std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();
  RigWorld world;
  // The monitors, only those the scene and the options name; the loop knows none by name.
  RegimeGuard regime;
  ConvergenceGuard convergence;
  std::vector<RunMonitor*> monitors{&regime, &convergence};
  std::optional<CycleRecorder> cycles;
  std::optional<RampSpeedAverage> ramp;
  std::optional<SidewaysDrift> drift;
  std::optional<StepObserver> observer;
  std::optional<HallChannel> hall;
  std::vector<PhoneChannel> phones;
  std::optional<TrajectoryRecorder> trajectory;
  RunExtremes extremes;
  std::optional<DriveStats> drive;

  long long steps = 0;  // the scene's duration in steps
  long long step = 0;   // taken
  PlateState state;
  PlateState previous;
  double t_previous = 0.0;
  std::optional<RunFailure> failure;
  std::optional<double> interrupted_at;
  bool ended = false;
};

RunLoop::RunLoop(const CompiledRig& rig, const RunOptions& options, RunRecording* recording)
    : impl_(std::make_unique<Impl>(rig, options, recording)) {
  Impl& r = *impl_;
  if (options.record_cycles && recording != nullptr) r.monitors.push_back(&r.cycles.emplace());
  if (rig.roller_speed_ramp) r.monitors.push_back(&r.ramp.emplace());
  // Skewed axes: the drift read over the run's second half, after the slip along y has died out
  // (within about v_r / (mu_k g), 0.6 s for the minimal scene; docs/physics.md).
  if (rig.rollers.skew != 0.0) r.monitors.push_back(&r.drift.emplace(0.5 * rig.world.duration));
  if (options.observer) r.observer.emplace(options.observer, &r.regime.monitor());
  if (rig.sensor && !rig.magnets.empty()) {
    r.hall.emplace(rig, options.record_hall ? r.keep : nullptr,
                   r.observer ? r.observer->new_samples() : nullptr);
    r.monitors.push_back(&*r.hall);
    if (r.observer) r.observer->set_estimator(&r.hall->estimator());
  }
  if (options.record_phones && r.keep != nullptr) {
    r.phones.reserve(rig.phones.size());  // the monitors point into it
    for (std::size_t i = 0; i < rig.phones.size(); ++i)
      r.monitors.push_back(&r.phones.emplace_back(rig, i, *r.keep));
  }
  if (options.record_trajectory && r.keep != nullptr)
    r.monitors.push_back(&r.trajectory.emplace(*r.keep));
  if (r.observer) r.monitors.push_back(&*r.observer);
  r.monitors.push_back(&r.extremes);
  if (rig.drive) r.monitors.push_back(&r.drive.emplace(rig));

  r.state = r.world.plate();
  for (RunMonitor* m : r.monitors) m->start(r.world, r.state);
  r.previous = r.state;
  r.steps = std::llround(rig.world.duration / rig.world.time_step);
  r.ended = r.steps <= 0;
}

RunLoop::~RunLoop() = default;

bool RunLoop::step() {
  Impl& r = *impl_;
  if (r.ended) return false;
  if (r.options.stop != nullptr && r.options.stop->load(std::memory_order_relaxed)) {
    r.interrupted_at = r.world.time();
    r.ended = true;
    return false;
  }
  if (r.options.progress && r.step % 1000 == 0) r.options.progress(r.world.time());
  r.world.step();
  ++r.step;
  r.state = r.world.plate();
  const std::array<RollerContact, 2> contacts = r.world.contacts();
  const std::array<double, 2> surface = r.world.roller_surface_speeds();
  const StepContext step{r.world.time(), r.t_previous, r.state, r.previous,
                         contacts,       surface,      r.world};
  // The guards first: what a guard stopped is not recorded, so the outputs hold every
  // trustworthy step.
  for (RunMonitor* m : r.monitors)
    if ((r.failure = m->check(step))) break;
  if (r.failure) {
    r.ended = true;
    return false;
  }
  for (RunMonitor* m : r.monitors) m->record(step);
  r.previous = r.state;
  r.t_previous = step.t;
  r.ended = r.step >= r.steps;
  return !r.ended;
}

bool RunLoop::ended() const {
  return impl_->ended;
}

double RunLoop::time() const {
  return impl_->world.time();
}

RunSummary RunLoop::finish(std::optional<SolverResidual>& unconverged) {
  Impl& r = *impl_;
  const CompiledRig& rig = r.rig;
  const RunOptions& options = r.options;
  RunRecording* recording = r.recording;
  const std::optional<HallChannel>& hall = r.hall;
  const OscillationTracker& tracker = r.regime.monitor().tracker();
  // The closed forms' g: what presses the plate on its rollers (g cos(tilt)).
  const double g = rig.gravity_normal;
  RunSummary out;
  rig_figures(rig, out);
  out.interrupted_at = r.interrupted_at;
  unconverged = r.convergence.unconverged();
  out.steps = r.world.steps();
  out.duration = r.world.time();
  out.plate_speed_max = r.extremes.plate_speed_max;
  if (r.drift) out.drift_speed = r.drift->speed();
  out.drift_speed_theory = rig.drift_speed;
  out.min_normal_force = r.extremes.min_normal_force;
  out.max_penetration = r.extremes.max_penetration;
  if (r.cycles) recording->cycles = r.cycles->cycles();
  if (r.ramp) {
    out.roller_speed = r.ramp->mean(0).value_or(rig.roller_speed_ramp->at(0.0));
    out.roller_speed_1 = r.ramp->mean(1).value_or(rig.roller_speed_ramp_roller_1->at(0.0));
  }
  if (r.failure) out.failure = r.failure->message;
  if (r.drive) {
    out.drive = r.drive->report();
    out.roller_speed = std::fabs(out.drive->roller_speeds[0]);
    out.roller_speed_1 = std::fabs(out.drive->roller_speeds[1]);
  }
  if (!tracker.turning_amplitudes().empty()) {
    out.amplitude_start = tracker.turning_amplitudes().front();
    out.amplitude_end = tracker.turning_amplitudes().back();
  }
  out.amplitude_drift_per_period = tracker.amplitude_drift_per_period();
  if (hall) out.estimator = hall->estimator().report();
  if (hall && options.record_hall && recording != nullptr)
    recording->periods = hall->estimator().periods();
  if (rig.warming)
    out.warming = warming_report(
        *rig.warming, hall ? hall->estimator().periods() : std::vector<EstimatedPeriod>{},
        rig.rollers.spacing, rig.plate.h_c, g, out.duration);
  // The rollers' surface speed: the set one, or the drive's mean under load; the slower roller's
  // where the two differ.
  const double surface_speed =
      std::min(out.roller_speed * rig.roller_radii[0], out.roller_speed_1 * rig.roller_radii[1]);
  out.slip_margin = out.plate_speed_max > 0.0 ? surface_speed / out.plate_speed_max
                                              : std::numeric_limits<double>::infinity();

  if (rig.rollers.runout > 0.0) {
    out.runout = rig.rollers.runout;
    const double k = std::sqrt(rig.plate.inertia_pitch / rig.plate.mass);
    out.runout_threshold =
        runout_hop_threshold(rig.rollers.spacing, k, g, out.roller_speed,
                             rig.rollers.runout_phase[0] + rig.rollers.runout_phase[1],
                             std::fabs(rig.plate_desc.offset), rig.friction.mu_k * rig.plate.h_c);
  }

  const RegimeFinding finding = r.regime.monitor().finding(r.failure);
  // A clipped oscillation's period is read after its last stick.
  const double harmonic_since = add_regime(rig, finding, out, recording);
  if (const auto p = tracker.period(harmonic_since)) {
    out.period_trajectory = p->slope;
    out.period_trajectory_err = p->slope_std_error;
    out.oscillation_centre = tracker.centre(harmonic_since);
  }
  if (out.estimator && out.period_trajectory)
    out.estimator_disagreement =
        cross_check(*out.estimator, *out.period_trajectory, out.clock_error.value_or(0.0));

  decide_headline(out);

  out.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - r.wall_start).count();
  out.real_time_factor = out.duration / out.wall_s;
  out.steps_per_second = static_cast<double>(out.steps) / out.wall_s;
  return out;
}

// One run at the rig's own solver iterations. `unconverged` is set when the convergence check
// stopped it (the run's failure then says so).
static RunSummary run_once(const CompiledRig& rig, const RunOptions& options,
                           RunRecording* recording, std::optional<SolverResidual>& unconverged) {
  RunLoop loop(rig, options, recording);
  while (loop.step()) {
  }
  return loop.finish(unconverged);
}

RunSummary run_experiment(const CompiledRig& rig, const RunOptions& options,
                          RunRecording* recording) {
  const auto wall_start = std::chrono::steady_clock::now();
  std::optional<SolverResidual> unconverged;
  RunSummary out = run_once(rig, options, recording, unconverged);
  if (!unconverged || out.interrupted_at) return out;
  // The solver did not converge: run again from the start at twice the iterations, up to the cap,
  // so that the result is exactly a run of the scene at the iterations it ends with. A run that
  // hands its steps to an observer (a video) has already shown them, and stops instead.
  const int asked = rig.world.solver_iterations;
  std::string history;
  int iterations = asked;
  double previous_error = 0.0;
  while (unconverged) {
    history += fmt::format("{}{} (t = {:.6f} s, a normal force {:.3g} % of the weight off)",
                           history.empty() ? "" : ", ", iterations, unconverged->time,
                           100.0 * unconverged->relative());
    const SolverRetry retry =
        solver_retry(iterations, kMaxSolverIterations, unconverged->error, previous_error,
                     static_cast<bool>(options.observer), history, rig.world.time_step);
    previous_error = unconverged->error;
    if (!retry.iterations) {
      out.failure = *out.failure + "; " + retry.advice;
      out.regime_evidence = *out.failure;
      if (iterations != asked) out.solver_iterations_raised = "from " + history;
      break;
    }
    iterations = *retry.iterations;
    if (recording != nullptr) *recording = RunRecording{};
    if (options.stream != nullptr) options.stream->restart();
    unconverged.reset();
    out = run_once(with_solver_iterations(rig, iterations), options, recording, unconverged);
    if (!unconverged)
      out.solver_iterations_raised = fmt::format(
          "from {} to {}: the contact solver had not converged at {}", asked, iterations, history);
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  out.real_time_factor = out.duration / out.wall_s;
  out.steps_per_second = static_cast<double>(out.steps) / out.wall_s;
  return out;
}

RunSummary run_experiment(const Scene& scene, const RunOptions& options, RunRecording* recording) {
  return run_experiment(compile_rig(scene), options, recording);
}

}  // namespace fl
