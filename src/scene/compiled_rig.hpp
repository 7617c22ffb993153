// The rig compiled from its scene, once: every quantity the physics, the sensor, the regime
// diagnosis, the outputs and the renderer derive from a Scene (the plate's mass properties and
// h_c, the drive's layout and ratios, the rollers' speed, the oscillation's angular frequency and
// periods, the slip threshold, the integrator's predicted bias...), computed in one place by one
// function per formula and read by every layer instead of being recomputed.
//
// A CompiledRig is immutable: change the Scene and compile again (sweeps and compare do).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/analytic_model.hpp"
#include "core/roller_warming.hpp"
#include "scene/drive_layout.hpp"
#include "scene/scene.hpp"

namespace fl {

// The drive's gear train as built (scenes with a `drive`).
struct CompiledDrive {
  DriveDesc parts;  // the motor, the stages and the gears, as the scene gives them
  DriveLayout layout;
  std::vector<double> shaft_ratios;  // each shaft's speed over the motor's, signed, from the teeth
  double gearbox_ratio = 1.0;        // the gearbox's speed-up, motor to roller 0 (|ratio|)
  double inertia_at_motor = 0.0;     // kg m^2, the whole train seen at the motor (sum I_k u_k^2)
  double motor_sense = 1.0;          // +1 or -1: the motor's turning that gives the rollers' sense
  // The rollers' steady speed [rad/s] with the plate sliding on both (its friction torque
  // mu_k m g a at the rollers, G times that at the motor), on the motor's linear curve; nullopt
  // when that load stalls the motor. With a duty ramp, at its smallest duty (the ramp stalls
  // the motor somewhere when this is nullopt).
  std::optional<double> roller_speed_loaded;
  double stall_load_torque = 0.0;  // N m at the motor, of that load
};

// Where the plate's friction comes from: what a run reports and a video tells beside the law.
struct FrictionSource {
  std::optional<std::string> paper_material;  // the paper's Table I key, when the law is its row
  std::optional<Measured> paper_period;       // T +- dT [s], the paper's for that material
  std::optional<Measured> paper_mu_k;
  double temperature = 300.0;    // K, of the rollers at the start
  bool temperature_set = false;  // the scene named it (videos show it then)
};

struct CompiledRig {
  // What the rig is built of, as its scene describes it; the scene's outputs, video settings and
  // expected regime are not the rig's and stay with the scene. Each value is read from one place:
  // l is rollers.spacing, g world.gravity, the step world.time_step, the friction `friction`.
  std::string name;  // the scene's: a file stem or "inline"
  WorldDesc world;
  RollersDesc rollers;
  PlateDesc plate_desc;  // the plate's size, material, payload, blocks and start
  std::vector<MagnetDesc> magnets;
  std::optional<SensorDesc> sensor;
  std::vector<PhoneDesc> phones;   // phones' sensors (an accelerometer's mass is in `plate`)
  std::optional<FrameDesc> frame;  // absent: no frame, no guides, no mesh
  FrictionSource friction_source;

  // The plate as built (slab, payload, blocks, magnets).
  PlateMass plate;
  FrictionLaw friction;  // plate on the rollers (the scene's friction as one law; its mu_k is
                         // the kinetic coefficient at large slip, Coulomb's mu_k)

  // The rollers' speed without load [rad/s]: rollers.speed for the ideal drive, the duty's
  // share of the motor's no-load speed times the gearbox's speed-up for the motor drive; for a
  // scene that ramps the speed or the duty, the largest the ramp reaches (the bounds of the run
  // rest on it).
  double roller_speed_nominal = 0.0;
  // What the scene schedules over time, when it does: the rollers' speed [rad/s] (ideal drive,
  // rollers.speed_ramp) or the motor's duty (drive.motor.duty_ramp).
  std::optional<Ramp> roller_speed_ramp;
  // Roller 1's schedule: its own when the ramp gives two speeds, else roller 0's; present exactly
  // when roller_speed_ramp is.
  std::optional<Ramp> roller_speed_ramp_roller_1;
  std::optional<Ramp> duty_ramp;
  std::optional<CompiledDrive> drive;
  // Rollers warming from friction.temperature (friction.warming): mu_k over time, `friction`
  // being the law at the start.
  std::optional<RollerWarming> warming;

  // The analytic oscillator for this plate with its rollers turning inward. `restoring` is false
  // when l <= 2 mu_k h_c; the thick-plate quantities are then absent. (It does not look at
  // rollers.sense: a scene whose rollers turn outward keeps these values for comparison.)
  bool restoring = false;
  // g cos(world.tilt), what presses the plate on its rollers: every closed form below uses it
  // (core/tilted_rig.hpp); g on a level rig.
  double gravity_normal = 9.81;
  // The line through the plate's two contacts, against the level: world.tilt, plus
  // asin((a_1 - a_0) / l) for rollers of different radii on axes at one height (the plate rests
  // tilted on them). The world and every closed form use it as a tilted rig's tilt; a level rig of
  // equal rollers has 0 [rad].
  double contact_tilt = 0.0;
  // Each roller's radius [m] (index 0 at -l/2): rollers.radius, or [roller 0, roller 1].
  std::array<double, 2> roller_radii{0.010, 0.010};
  // How far apart the plate's two contacts are: l, and 2 rollers.rolling_resistance more for
  // rollers turning inward (less outward). Every closed form below uses it for l.
  double contact_spacing = 0.089;
  // x_eq, where a tilted rig's plate oscillates about (0 on a level one) [m].
  std::optional<double> oscillation_centre;
  // Skewed axes (rollers.skew): the plate's sideways drift once its slip along y has died out,
  // v_r sin(skew / 2) [m/s] (docs/physics.md); none without skew, with guide towers (they stop
  // it), or when the rollers' surface speeds differ or change (two speeds, a ramp).
  std::optional<double> drift_speed;
  double period_thin = 0.0;                    // s, the paper's formula
  std::optional<double> period_thick;          // s
  std::optional<double> omega;                 // rad/s, 2 pi / T_thick
  std::optional<double> integrator_bias;       // relative period error -(omega dt)^2 / 24
  std::optional<MuKUncertainty> conditioning;  // how errors in T, l, h_c carry into mu_k
  double amplitude_initial = 0.0;              // m, about x_eq, from plate.offset and velocity
  std::optional<double> tipping_amplitude;     // m, l/2 - mu_k h_c - |x_eq|
  // Roller speed [rad/s] at which the rollers' surface keeps up with the plate's largest speed
  // A omega (below it the plate sticks to a roller for part of each cycle).
  std::optional<double> slip_threshold;

  // The guide towers' friction on the plate (ABS on the slab), apart from mu_k.
  double guide_friction = 0.3;

  // The largest mu_k that leaves this plate a restoring force, l / (2 h_c); none for h_c <= 0
  // (a compare refit keeps its trials below it).
  std::optional<double> mu_k_restoring_limit;

  // What a run's guards hold it to (lab/run/regime_monitor.hpp), from the rig alone.
  struct RunGuards {
    double surface_speed = 0.0;  // m/s, the rollers' surface at their nominal speed
    // J: friction cannot drive the plate faster than the rollers' surface, and gravity gives at
    // most m g times the plate's length; ten times more energy than both is a numerical blow-up.
    double energy = 0.0;
    double penetration = 0.0;  // m: a plate deeper into a roller has failed numerically
    double speed = 0.0;        // m/s: and a plate faster than this
    double turn = 0.0;         // s, one turn of a roller at its nominal speed (0: still)
    // 1/s, a slip-dependent law's growth rate linearised about the rollers' speed (with a
    // restoring force, where it has a meaning).
    std::optional<double> linearised_growth;
  };
  RunGuards guards;
};

// Compiles a scene that passed check_scene (scene_checks.hpp). Throws std::invalid_argument when
// the drive's gears cannot span the rollers (drive_layout).
CompiledRig compile_rig(Scene scene);

// The same rig stepped at another time step: the step and what follows from it (the integrator's
// predicted bias) changed, nothing compiled again.
CompiledRig with_time_step(CompiledRig rig, double time_step);

// The same rig solved with another number of contact-solver iterations (nothing follows from it).
CompiledRig with_solver_iterations(CompiledRig rig, int iterations);

// The same, shared: what many readers hold (a sweep point, a run and its video).
std::shared_ptr<const CompiledRig> compile_rig_shared(Scene scene);

}  // namespace fl
