#include "lab/run/regime_monitor.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/friction_oscillator.hpp"
#include "core/units.hpp"
#include "lab/run/law_resolution.hpp"

namespace fl {
namespace {

// A normal force below this fraction of the plate's weight means the plate has lifted off.
constexpr double kLiftOffFraction = 1e-3;
// Rollers whose surfaces move on average at less than this fraction of the speed set, over the
// last quarter of the run, have stalled.
constexpr double kStallFraction = 0.1;
// A lift-off counts as a jump when the plate's bottom rose this far above the roller (less is a
// contact whose force dropped out for a step while the bodies still touched).
constexpr double kJumpHeight = 1e-6;  // m
// Lift-offs locked to the roller's turn: the mean resultant length of their phases. A tube off its
// shaft can only drop away from the plate in the half-turn in which its top accelerates downward,
// so its jumps' phases give at least 2/pi = 0.64 even spread evenly over that half; phases not
// locked give about 1/sqrt(n).
constexpr double kLockedResultant = 0.5;
// The first steps settle the resting contact.
constexpr int kSettleSteps = 3;

bool finite(const PlateState& s) {
  return std::isfinite(s.x) && std::isfinite(s.z) && std::isfinite(s.pitch) &&
         std::isfinite(s.vx) && std::isfinite(s.vz) && std::isfinite(s.pitch_rate);
}

}  // namespace

std::string regime_so_far(const RegimeFinding& f) {
  std::string line = f.since > 0.0
                         ? fmt::format("{} since t = {:.3f} s", regime_name(f.regime), f.since)
                         : std::string(regime_name(f.regime));
  if (f.jumps > 0)
    line += fmt::format("; {} jump{} off a roller, up to {:.1f} mm", f.jumps,
                        f.jumps == 1 ? "" : "s", f.highest_jump.value_or(0.0) * 1e3);
  return line;
}

RegimeMonitor::RegimeMonitor(const CompiledRig& rig)
    : rig_(rig),
      mass_(rig.plate.mass),
      inertia_(rig.plate.inertia_pitch),
      h_c_(rig.plate.h_c),
      slip_dependent_(rig.friction.depends_on_slip()),
      law_(rig.friction) {
  // The guards' bounds and the law's linearised growth are the compiled rig's.
  surface_speed_ = rig.guards.surface_speed;
  energy_bound_ = rig.guards.energy;
  penetration_bound_ = rig.guards.penetration;
  speed_bound_ = rig.guards.speed;
  // Offsets are read from the oscillation's centre: a tilted rig's x_eq, 0 on a level one.
  centre_ = rig.oscillation_centre.value_or(0.0);
  gravity_along_ = -rig.world.gravity * std::sin(rig.contact_tilt);
  tracker_ = OscillationTracker(centre_);
  start_abs_x_ = std::fabs(rig.plate_desc.offset - centre_);
  turn_ = rig.guards.turn;
  previous_x_ = rig.plate_desc.offset - centre_;
  z0_ = h_c_;
  linearised_growth_ = rig.guards.linearised_growth;
}

void RegimeMonitor::start(const PlateState& s) {
  tracker_.add(0.0, s.x, s.vx);
}

std::optional<RunFailure> RegimeMonitor::observe(double t, const PlateState& s,
                                                 const std::array<RollerContact, 2>& contacts,
                                                 const std::array<double, 2>& surface,
                                                 const std::array<double, 2>& roller_angles) {
  // Guards first: numbers the lab cannot trust stop the run.
  if (std::optional<RunFailure> failure = guard(t, s, contacts)) return failure;

  // Diagnosis.
  // Where the plate is from the oscillation's centre.
  const double x = s.x - centre_;
  tracker_.add(t, s.x, s.vx);
  last_t_ = t;
  if (!first_ && ((previous_x_ < 0.0 && x >= 0.0) || (previous_x_ > 0.0 && x <= 0.0))) ++crossings_;
  if (std::fabs(x) > max_abs_x_) {
    max_abs_x_ = std::fabs(x);
    x_at_max_ = t;
  }
  if (!first_ && ((previous_vx_ > 0.0 && s.vx <= 0.0) || (previous_vx_ < 0.0 && s.vx >= 0.0)) &&
      excursions_.size() < 16)
    excursions_.push_back(std::fabs(x));
  previous_vx_ = s.vx;
  previous_x_ = x;
  first_ = false;
  static_assert(kSettleSteps > 0);
  record_friction_direction(t, x, contacts);
  const long long step = std::llround(t / rig_.world.time_step);
  if (step < kSettleSteps) return std::nullopt;
  record_contacts(t, s, contacts, surface, roller_angles);
  return std::nullopt;
}

std::optional<RunFailure> RegimeMonitor::guard(double t, const PlateState& s,
                                               const std::array<RollerContact, 2>& contacts) const {
  if (!finite(s)) {
    return RunFailure{Regime::kNumericallyFailed, t, "plate", "state",
                      fmt::format("t = {:.6f} s: the plate's state is not finite (x = {}, z = {}, "
                                  "vx = {}); the time step is too large for this scene",
                                  t, s.x, s.z, s.vx)};
  }
  const double energy =
      0.5 * mass_ * (s.vx * s.vx + s.vz * s.vz) + 0.5 * inertia_ * s.pitch_rate * s.pitch_rate +
      mass_ * (rig_.gravity_normal * (s.z - z0_) + gravity_along_ * (rig_.plate_desc.offset - s.x));
  if (energy > energy_bound_) {
    return RunFailure{Regime::kNumericallyFailed, t, "plate", "energy",
                      fmt::format("t = {:.6f} s: the plate's energy {:.3g} J exceeds {:.3g} J, ten "
                                  "times what the rollers and gravity can give it: a numerical "
                                  "blow-up (try a smaller time step)",
                                  t, energy, energy_bound_)};
  }
  for (int i = 0; i < 2; ++i) {
    if (contacts[i].penetration > penetration_bound_) {
      return RunFailure{
          Regime::kNumericallyFailed, t, fmt::format("roller {}", i), "penetration",
          fmt::format("t = {:.6f} s: the plate sinks {:.3g} mm into roller {}, beyond "
                      "the {:.3g} mm the contact model tolerates (try a smaller time "
                      "step or more solver iterations)",
                      t, contacts[i].penetration * 1e3, i, penetration_bound_ * 1e3)};
    }
  }
  // Friction drives the plate toward the rollers' surface speed, never beyond it; a plate faster
  // than that (with room for a fall) has been thrown by the numerics.
  if (std::fabs(s.vx) > speed_bound_) {
    return RunFailure{
        Regime::kNumericallyFailed, t, "plate", "speed",
        fmt::format("t = {:.6f} s: the plate moves at {:.3g} m/s, more than twice what "
                    "the rollers (surface speed {:.3g} m/s) can drive: a numerical "
                    "blow-up (try a smaller time step)",
                    t, s.vx, surface_speed_)};
  }
  // Where the plate is from the oscillation's centre.
  const double x = s.x - centre_;
  // A step that carries the plate a quarter of the roller spacing resolves nothing of the motion.
  if (std::fabs(x - previous_x_) > 0.25 * rig_.rollers.spacing) {
    return RunFailure{
        Regime::kNumericallyFailed, t, "plate", "x",
        fmt::format("t = {:.6f} s: the plate jumped {:.1f} mm in one step of {:.3g} ms, "
                    "more than a quarter of the roller spacing: the time step is too "
                    "large for this scene",
                    t, (x - previous_x_) * 1e3, rig_.world.time_step * 1e3)};
  }
  // The plate leaves the rig when a roller is no longer under it, or it falls.
  const double half_l = 0.5 * rig_.rollers.spacing;
  const double half_length = 0.5 * rig_.plate_desc.length;
  if (std::fabs(s.x) + half_l > half_length || s.z < -rig_.rollers.radius) {
    return RunFailure{Regime::kLost, t, "plate", "x",
                      fmt::format("t = {:.6f} s: the plate left the rollers (centre of mass at x = "
                                  "{:.1f} mm, z = {:.1f} mm; a roller is no longer under it)",
                                  t, s.x * 1e3, s.z * 1e3)};
  }
  // Sideways: the lab's contacts are one point at each roller's middle (y = 0), so the plate
  // drifting along y (skewed axes) loses them when its edge comes there; within 1 mm of the edge
  // the contact already meets the box's rounded edge (Bullet's collision margin) and tilts.
  const double edge = 0.5 * rig_.plate_desc.width - 1e-3;
  if (!rig_.frame && std::fabs(s.y) > edge) {
    return RunFailure{
        Regime::kLost, t, "plate", "y",
        fmt::format("t = {:.6f} s: the plate drifted {:.1f} mm sideways, its edge within 1 mm of "
                    "the rollers' middles, where the lab's contacts are (one point a roller; a "
                    "real rig's {:.0f} mm rollers would hold it up to {:.1f} mm): shorten the run "
                    "or lessen rollers.skew",
                    t, s.y * 1e3, rig_.rollers.length * 1e3,
                    0.5e3 * (rig_.rollers.length + rig_.plate_desc.width))};
  }
  return std::nullopt;
}

void RegimeMonitor::record_friction_direction(double t, double x,
                                              const std::array<RollerContact, 2>& contacts) {
  // Which way friction pushes while the plate rests on both rollers: toward the centre is the
  // restoring force of the oscillator; away from it, there is none. A plate that left a roller
  // within the last turn is landing, not resting: the impacts share its weight as they come.
  const double weight = mass_ * rig_.gravity_normal;
  const bool landing = last_lift_off_ && t - *last_lift_off_ <= turn_;
  if (contacts[0].normal_force > 1e-2 * weight && contacts[1].normal_force > 1e-2 * weight &&
      std::fabs(x) > 1e-6 && !landing) {
    // The net friction with the slope's pull (a tilted rig's friction balances it at x_eq).
    const double friction =
        contacts[0].friction_force + contacts[1].friction_force + mass_ * gravity_along_;
    // A plate held at rest feels no net friction but the solver's round-off: not a direction.
    const bool held = contacts[0].stuck && contacts[1].stuck;
    if (!held && friction * x > 0.0) {
      if (friction_away_ == 0) {
        away_first_t_ = t;
        away_first_x_ = x;
        away_first_force_ = friction;
      }
      ++friction_away_;
    } else if (!held && friction * x < 0.0) {
      ++friction_toward_;
    }
  }
}

void RegimeMonitor::record_contacts(double t, const PlateState& s,
                                    const std::array<RollerContact, 2>& contacts,
                                    const std::array<double, 2>& surface,
                                    const std::array<double, 2>& roller_angles) {
  const double weight = mass_ * rig_.gravity_normal;

  for (int i = 0; i < 2; ++i) {
    const double speed = std::fabs(surface[i]);
    const double ratio = speed > 0.0 ? std::fabs(surface[i] - s.vx) / speed : 0.0;
    slip_ratio_min_ = std::min(slip_ratio_min_, ratio);
    const bool lifted = contacts[i].normal_force < kLiftOffFraction * weight;
    if (lifted) last_lift_off_ = t;
    if (lifted && !tip_since_) {
      tip_since_ = t;
      tip_roller_ = i;
      tip_force_ = contacts[i].normal_force;
    }
    const std::size_t k = static_cast<std::size_t>(i);
    if (lifted && !lifted_[k] && lift_offs_.size() < 100000)
      lift_offs_.push_back({i, t, t, 0.0, roller_angles[k], true});
    if (lifted_[k]) {
      for (auto it = lift_offs_.rbegin(); it != lift_offs_.rend(); ++it)
        if (it->roller == i && it->open) {
          it->end = t;
          if (lifted) {
            it->height = std::max(it->height, contacts[i].gap);
          } else {
            it->open = false;
          }
          break;
        }
    }
    lifted_[k] = lifted;
  }
  const double surface_mean = 0.5 * (std::fabs(surface[0]) + std::fabs(surface[1]));
  if (surface_mean > kStallFraction * surface_speed_) turning_until_ = t;
  if (t >= 0.75 * rig_.world.duration) {
    late_surface_sum_ += surface_mean;
    ++late_steps_;
  }
  // Stick episodes: a stretch of steps in which the plate is held to one roller's surface.
  const int stuck_roller = contacts[0].stuck ? 0 : (contacts[1].stuck ? 1 : -1);
  StickEpisode* open = !sticks_.empty() && sticks_.back().open ? &sticks_.back() : nullptr;
  if (open && open->roller != stuck_roller) {
    open->open = false;
    open = nullptr;
  }
  if (stuck_roller >= 0) {
    if (!open) sticks_.push_back({stuck_roller, stick_start(stuck_roller, t), t, 0, true});
    sticks_.back().end = t;
    ++sticks_.back().steps;
  }
  for (int i = 0; i < 2; ++i) {
    slips_[i][1] = slips_[i][0];
    slips_[i][0] = s.vx - surface[i];
  }
  ++slip_steps_;
}

double RegimeMonitor::stick_start(int roller, double t) const {
  // The slip at the last two steps, extrapolated to where it reaches zero: the stick began there
  // (between the last step and this one), not at this step. The same rule for every stick, so
  // the intervals between sticks, a stick-slip cycle's period, carry no whole-step rounding.
  if (slip_steps_ < 2) return t;
  const double last = slips_[roller][0], before = slips_[roller][1];
  if (!(std::fabs(last) < std::fabs(before)) || last * before <= 0.0) return t;
  const double steps_after_last = std::clamp(last / (before - last), 0.0, 1.0);
  return t - rig_.world.time_step * (1.0 - steps_after_last);
}

RegimeFinding RegimeMonitor::finding(const std::optional<RunFailure>& failure) const {
  RegimeFinding f;
  if (failure && failure->regime == Regime::kNumericallyFailed) {
    f.regime = Regime::kNumericallyFailed;
    f.since = failure->time;
    f.evidence = failure->message;
    return f;
  }
  if (no_restoring_force(failure, f)) return f;
  // Brief lift-offs that keep coming and going are jumps, not a tip: the motion is read on, and
  // the jumps are reported with it.
  const bool jumps = lift_offs_are_jumps();
  if (jumps) record_jumps(f);
  // Lifting off a roller is the cause when it came first; the plate may have left the rig after.
  if (!jumps && tip_since_ && (!failure || *tip_since_ <= failure->time)) {
    f.regime = Regime::kTips;
    f.since = *tip_since_;
    f.evidence = fmt::format(
        "the normal force on roller {} fell to {:.3g} N (weight {:.3g} N) at "
        "t = {:.4f} s: the plate lifted off it{}",
        tip_roller_, tip_force_, mass_ * rig_.gravity_normal, *tip_since_,
        failure ? "; then " + failure->message : std::string());
    return f;
  }
  if (failure) {
    f.regime = failure->regime;
    f.since = failure->time;
    f.evidence = failure->message;
    return f;
  }
  if (!jumps && tip_since_) {
    f.regime = Regime::kTips;
    f.since = *tip_since_;
    f.evidence = fmt::format(
        "the normal force on roller {} fell to {:.3g} N (weight {:.3g} N) at "
        "t = {:.4f} s: the plate lifted off it",
        tip_roller_, tip_force_, mass_ * rig_.gravity_normal, *tip_since_);
    return f;
  }
  if (surface_speed_ == 0.0) {
    f.regime = Regime::kSticks;
    f.evidence = "the rollers do not turn: friction holds the plate";
    return f;
  }
  // Rollers that barely turn over the last quarter of the run (a motor stalled by the plate's
  // friction): friction holds the plate to them.
  if (late_steps_ > 0 && late_surface_sum_ / late_steps_ < kStallFraction * surface_speed_) {
    f.regime = Regime::kSticks;
    f.since = turning_until_;
    f.evidence = fmt::format(
        "the rollers stalled at t = {:.4f} s: over the last quarter of the run their surfaces "
        "moved at {:.3g} m/s "
        "on average, {:.1f} % of the {:.3g} m/s set; friction holds the plate to them (it rests "
        "at x = {:+.2f} mm)",
        turning_until_, late_surface_sum_ / late_steps_,
        100.0 * late_surface_sum_ / late_steps_ / surface_speed_, surface_speed_,
        previous_x_ * 1e3);
    return f;
  }
  read_motion(jumps, f);
  return f;
}

bool RegimeMonitor::no_restoring_force(const std::optional<RunFailure>& failure,
                                       RegimeFinding& f) const {
  // Friction that pushes the plate away from the centre while it rests on both rollers: no
  // restoring force (whatever follows: a lift-off, a drift, the plate leaving the rig).
  if (friction_away_ > friction_toward_) {
    f.regime = Regime::kNoRestoringForce;
    f.since = away_first_t_;
    f.evidence = fmt::format(
        "while the plate rested on both rollers, the net friction force pushed it "
        "away from the centre in {} of {} steps (first at t = {:.4f} s: {:+.3g} N "
        "at x = {:+.2f} mm){}",
        friction_away_, friction_away_ + friction_toward_, away_first_t_, away_first_force_,
        away_first_x_ * 1e3, failure ? "; " + failure->message : std::string());
    return true;
  }
  // Thrown farther out at each turn until it left the rig: friction drives the plate away.
  if (failure && failure->regime == Regime::kLost && !excursions_.empty() &&
      std::fabs(previous_x_) > 1.5 * std::max(start_abs_x_, 1e-3)) {
    // The start, each turning point, and where the plate was when it left: the last three grow.
    std::vector<double> path{start_abs_x_};
    path.insert(path.end(), excursions_.begin(), excursions_.end());
    path.push_back(std::fabs(previous_x_));
    const std::size_t n = path.size();
    const bool growing = path[n - 1] > path[n - 2] && (n < 3 || path[n - 2] > path[n - 3]);
    std::string list;
    for (const double e : path) list += fmt::format("{}{:.1f}", list.empty() ? "" : ", ", e * 1e3);
    if (growing) {
      f.regime = Regime::kNoRestoringForce;
      f.since = 0.0;
      f.evidence = fmt::format(
          "each excursion went farther from the centre ({} mm) until the plate left "
          "the rig: friction drives it away{}; {}",
          list,
          tip_since_
              ? fmt::format(" (it lifted off roller {} at t = {:.4f} s)", tip_roller_, *tip_since_)
              : std::string(),
          failure->message);
      return true;
    }
  }
  // Drifting off: the plate never came back through the centre and got farther out.
  if (crossings_ == 0 && max_abs_x_ > 1.5 * std::max(start_abs_x_, 1e-3)) {
    f.regime = Regime::kNoRestoringForce;
    f.since = 0.0;
    f.evidence = fmt::format(
        "the plate moved away from the centre, from |x| = {:.1f} mm to {:.1f} mm "
        "at t = {:.3f} s, and never came back{}",
        start_abs_x_ * 1e3, max_abs_x_ * 1e3, x_at_max_,
        failure ? "; " + failure->message : std::string());
    return true;
  }
  return false;
}

void RegimeMonitor::record_jumps(RegimeFinding& f) const {
  f.jump_list = this->jumps();
  f.jumps = static_cast<int>(f.jump_list.size());
  f.first_jump = f.jump_list.front().start;
  double longest = 0.0, highest = 0.0;
  for (const PlateJump& l : f.jump_list) {
    longest = std::max(longest, l.end - l.start);
    highest = std::max(highest, l.height);
  }
  f.longest_jump = longest;
  f.highest_jump = highest;
}

void RegimeMonitor::read_motion(bool jumped, RegimeFinding& f) const {
  MotionEvidence evidence;
  evidence.sticks = sticks_;
  evidence.crossings = tracker_.crossings();
  evidence.turning_times = tracker_.turning_times();
  evidence.turning_amplitudes = tracker_.turning_amplitudes();
  evidence.amplitude_start = start_abs_x_;
  evidence.duration = last_t_;
  evidence.time_step = rig_.world.time_step;
  evidence.slip_dependent = slip_dependent_;
  MotionFinding motion = diagnose_motion(evidence);
  f.regime = motion.regime;
  f.since = motion.since;
  f.evidence = motion.evidence;
  // A law the step does not resolve where the plate used it: what the run shows is the step's.
  std::optional<double> growth;  // the larger of the measured and the law's linearised rate
  if (slip_dependent_) {
    growth = linearised_growth_;
    if (motion.growth_rate && (!growth || std::fabs(*motion.growth_rate) > std::fabs(*growth)))
      growth = motion.growth_rate;
  }
  if (const std::optional<UnresolvedLaw> unresolved = unresolved_law(
          law_, rig_.gravity_normal, rig_.world.time_step, !sticks_.empty(), growth)) {
    f.regime = Regime::kNumericallyFailed;
    f.since = 0.0;
    f.evidence = unresolved->reason + " (the run looked " + regime_name(motion.regime) + ": " +
                 motion.evidence + ")";
    f.motion = std::move(motion);
    return;
  }
  if (motion.regime == Regime::kOscillates && sticks_.empty())
    f.evidence = fmt::format(
        "both rollers slipped throughout (the plate's speed stayed at least "
        "{:.1f} % of the surface speed away from each roller's)",
        100.0 * slip_ratio_min_);
  if (jumped)
    f.evidence += fmt::format(
        "; the plate jumped off a roller {} times from t = {:.4f} s (locked to the "
        "roller's turn), each time back within {:.1f} ms, at most {:.3f} mm high",
        f.jumps, *f.first_jump, *f.longest_jump * 1e3, *f.highest_jump * 1e3);
  f.motion = std::move(motion);
}

std::vector<PlateJump> RegimeMonitor::jumps() const {
  std::vector<PlateJump> out;
  for (const PlateJump& l : lift_offs_)
    if (l.height > kJumpHeight) out.push_back(l);
  return out;
}

bool RegimeMonitor::lift_offs_are_jumps() const {
  // A tube off its shaft drops away under the plate at the same point of each turn
  // (core/runout.hpp): the plate's jumps are locked to the roller's angle. A plate that tips lifts
  // off (and may chatter) near its turning points, or stays off; on true rollers a roller's angle
  // changes nothing, so nothing can be locked to it. Each roller's jumps are read against its own
  // angle, which a drive under load turns a little slower than the speed set.
  if (rig_.rollers.runout <= 0.0 || lift_offs_.empty() || turn_ <= 0.0) return false;
  // A lift-off still on at the end that has lasted a turn and a quarter of the run is the plate off
  // a roller for good.
  for (const PlateJump& l : lift_offs_)
    if (l.open && last_t_ - l.start > std::max(turn_, 0.25 * last_t_)) return false;
  const std::vector<PlateJump> real = jumps();
  bool any = false;
  for (int roller = 0; roller < 2; ++roller) {
    double c = 0.0, s = 0.0;
    int n = 0;
    for (const PlateJump& l : real) {
      if (l.roller != roller) continue;
      c += std::cos(l.roller_angle);
      s += std::sin(l.roller_angle);
      ++n;
    }
    if (n == 0) continue;
    if (n < 3 || std::hypot(c, s) < kLockedResultant * n) return false;
    any = true;
  }
  return any;
}

}  // namespace fl
