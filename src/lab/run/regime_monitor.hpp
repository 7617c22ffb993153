// Which physical regime a run is in, diagnosed from the simulation itself (not from the
// formula), with when it began and the evidence; and the guards that stop a run whose numerics
// or whose plate have left what the lab can trust.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/oscillation_tracker.hpp"
#include "core/regime.hpp"
#include "lab/run/motion_diagnosis.hpp"
#include "physics/rig_world.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// One stretch of steps in which a roller carried (almost) nothing of the plate.
struct PlateJump {
  int roller = 0;
  double start = 0.0;   // s, the first step off the roller
  double end = 0.0;     // s, the first step back on it (the run's end if it never came back)
  double height = 0.0;  // m, the largest gap between the plate's bottom and the roller meanwhile
  double roller_angle = 0.0;  // rad, the roller's angle since the start when the plate left it
  bool open = true;           // still off the roller
};

struct RegimeFinding {
  Regime regime = Regime::kOscillates;
  double since = 0.0;    // s, when the evidence first appeared (0 for a clean oscillation)
  std::string evidence;  // which force, which speed, which quantity
  // The trajectory's numbers (clip, stick-slip cycle, growth rate), when the plate stayed on both
  // rollers with a restoring force and the motion itself was read (lab/run/motion_diagnosis.hpp).
  std::optional<MotionFinding> motion;
  // Jumps: the plate left a roller and came back, again and again locked to the rollers' angle (a
  // roller off its shaft), rather than tipping. Each one; how many, when the first began, the
  // longest, the highest.
  std::vector<PlateJump> jump_list;
  int jumps = 0;
  std::optional<double> first_jump;    // s
  std::optional<double> longest_jump;  // s
  std::optional<double> highest_jump;  // m
};

// A guard that fired: the run stops here.
struct RunFailure {
  Regime regime = Regime::kNumericallyFailed;  // or kLost
  double time = 0.0;                           // s
  std::string body;                            // "plate", "roller 0", ...
  std::string quantity;                        // "x", "energy", "penetration", ...
  std::string message;                         // the whole sentence
};

// The diagnosis so far as one line: "oscillates since t = 1.234 s; 2 jumps off a roller, up to
// 0.3 mm" (what a video and a live page show while the run goes on).
std::string regime_so_far(const RegimeFinding& finding);

class RegimeMonitor {
 public:
  // The rig must outlive the monitor.
  explicit RegimeMonitor(const CompiledRig& rig);

  // The plate at t = 0, before the first step.
  void start(const PlateState& plate);

  // One step's state. Returns a failure when a guard fires; the run must stop then.
  // `surface` is each roller's top's velocity along +x [m/s] this step, `roller_angles` each
  // roller's angle since the start [rad].
  std::optional<RunFailure> observe(double t, const PlateState& plate,
                                    const std::array<RollerContact, 2>& contacts,
                                    const std::array<double, 2>& surface,
                                    const std::array<double, 2>& roller_angles);

  // The diagnosis so far (call after the last step, or after a failure).
  RegimeFinding finding(const std::optional<RunFailure>& failure) const;

  // The smallest slip speed seen at each roller relative to its surface speed (1 = the plate at
  // rest against the roller's surface, 0 = the plate moving with it).
  double slip_margin_observed() const { return slip_ratio_min_; }

  // The trajectory's crossings and turning points over the steps the guards let through.
  const OscillationTracker& tracker() const { return tracker_; }

 private:
  // The finding's parts: no restoring force (friction pushing the plate away, excursions that
  // grew until it left, a drift that never came back), written into `f` when so; the jumps; and
  // the motion read from the turning points and sticks, with a law the step does not resolve.
  bool no_restoring_force(const std::optional<RunFailure>& failure, RegimeFinding& f) const;
  void record_jumps(RegimeFinding& f) const;
  void read_motion(bool jumped, RegimeFinding& f) const;
  // The guards of one step: a state the lab cannot trust or a plate that left the rig, as the
  // failure that stops the run; none when the step may be diagnosed.
  std::optional<RunFailure> guard(double t, const PlateState& plate,
                                  const std::array<RollerContact, 2>& contacts) const;
  // Which way friction pushes the plate, resting on both rollers, `x` from the centre.
  void record_friction_direction(double t, double x, const std::array<RollerContact, 2>& contacts);
  // Each roller's slip, lift-offs and stick episodes, and how fast the rollers turn.
  void record_contacts(double t, const PlateState& plate,
                       const std::array<RollerContact, 2>& contacts,
                       const std::array<double, 2>& surface,
                       const std::array<double, 2>& roller_angles);
  // When a stick on `roller` found at step time t began, between the last step and t.
  double stick_start(int roller, double t) const;
  const CompiledRig& rig_;
  double mass_, inertia_, h_c_;
  bool slip_dependent_;
  FrictionLaw law_;
  std::optional<double> linearised_growth_;  // 1/s, a slip-dependent law's at the rollers' speed
  double surface_speed_;                     // m/s, the rollers' top without load (for the bounds)
  double energy_bound_;                      // J
  double penetration_bound_;
  double speed_bound_;        // m/s
  double start_abs_x_ = 0.0;  // m, from the centre
  double z0_ = 0.0;
  // The oscillation's centre (x_eq, 0 on a level rig) and the slope's pull per unit mass along +x,
  // -g sin(tilt) (m/s^2).
  double centre_ = 0.0;
  double gravity_along_ = 0.0;

  int crossings_ = 0;
  double previous_x_ = 0.0;
  bool first_ = true;
  double max_abs_x_ = 0.0;
  double previous_vx_ = 0.0;
  std::vector<double> excursions_;  // |x| at the first turning points, m
  double x_at_max_ = 0.0;

  double slip_ratio_min_ = 1e300;
  // The stick episodes the contacts reported, and the oscillation's crossings and turning points.
  std::vector<StickEpisode> sticks_;
  // The plate's slip on each roller (its speed less the roller's surface speed, m/s) at the last
  // two steps, to place a stick's start between steps.
  std::array<std::array<double, 2>, 2> slips_{};
  int slip_steps_ = 0;
  OscillationTracker tracker_;
  double last_t_ = 0.0;
  // The rollers' mean surface speed over the last quarter of the run.
  double late_surface_sum_ = 0.0;
  long long late_steps_ = 0;
  double turning_until_ = 0.0;  // s, the last step the rollers turned above the stall bound
  // Steps on both rollers whose net friction pushed the plate away from / toward the centre.
  long long friction_away_ = 0;
  long long friction_toward_ = 0;
  double away_first_t_ = 0.0, away_first_x_ = 0.0, away_first_force_ = 0.0;
  // Every stretch of steps in which a roller carried (almost) nothing of the plate.
  std::vector<PlateJump> lift_offs_;
  std::array<bool, 2> lifted_{};
  std::optional<double> last_lift_off_;  // s, the last step a roller carried (almost) nothing
  double turn_ = 0.0;                    // s, one turn of the rollers at the speed set
  // The lift-offs in which the plate rose above the roller.
  std::vector<PlateJump> jumps() const;
  // Whether the lift-offs are jumps (on rollers with run-out, over within a turn, and locked to
  // the lifted roller's angle), not a tip.
  bool lift_offs_are_jumps() const;
  std::optional<double> tip_since_;
  int tip_roller_ = -1;
  double tip_force_ = 0.0;
};

}  // namespace fl
