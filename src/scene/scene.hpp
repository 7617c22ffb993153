// A scene: the plain description of one experiment, in SI units, with no Bullet, GL or file types.
// The YAML loader (scene_yaml.hpp) fills it; tests and sweeps may build or change it directly;
// the physics builder makes a world of exactly the parts it names. Defaults live here, once.
//
// Coordinates: x along the plate's motion, z up, the rollers' axes along y at x = -l/2 and
// x = +l/2. The contact line (the rollers' tops) is at z = 0.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/friction_law.hpp"
#include "core/ramp.hpp"
#include "core/regime.hpp"
#include "core/units.hpp"
#include "scene/video_yaml.hpp"
#include "text/said.hpp"

namespace fl {

using Vec3 = std::array<double, 3>;

struct WorldDesc {
  double gravity = 9.81;  // m/s^2, pulls along -z on a level rig
  // rad: the line through the rollers' tops rises by this angle toward +x (a rig not level); the
  // rig's frame stays as above and gravity turns: (-g sin tilt, 0, -g cos tilt).
  double tilt = 0.0;
  double time_step = 1.0 / 1000;  // s, fixed
  int solver_iterations = 10;     // sequential-impulse iterations per step
  double duration = 10.0;         // s of simulated time
  std::uint64_t seed = 1;         // sensor noise and jitter
};

enum class RollerSense { kInward, kOutward };  // which way the rollers' tops turn

struct RollersDesc {
  double spacing = 0.089;  // l, m, between the two axes
  double radius = 0.010;   // a, m (roller 0's, when the two differ)
  // Roller 1's own radius (rollers.radius: [roller 0, roller 1]): its top then stands higher or
  // lower than roller 0's, and the plate lies tilted. Absent: both `radius`.
  std::optional<double> radius_roller_1;
  double length = 0.100;              // m, along y
  double speed = 167.55160819145563;  // rad/s (1600 rpm), each roller (ideal drive only)
  // rad/s: roller 1's own speed where the two differ (rollers.speed: [roller 0, roller 1]; two
  // motors, a slipping belt); `speed` is then roller 0's. Absent: both turn at `speed`.
  std::optional<double> speed_roller_1;
  // The speed over time instead (ideal drive only; values in rad/s, times in s): piecewise
  // linear, held after its last point. Empty: the constant `speed`.
  std::vector<RampPoint> speed_ramp;
  // Roller 1's own schedule, when the ramp's points give two speeds [roller 0, roller 1]
  // (`speed_ramp` is then roller 0's); empty: both follow `speed_ramp`.
  std::vector<RampPoint> speed_ramp_roller_1;
  double wall = 0.0015;     // m, the PVC tube's wall (its mass and inertia, when driven)
  double density = 1400.0;  // kg/m^3 (PVC)
  RollerSense sense = RollerSense::kInward;
  // Run-out: each tube's axis sits this far off its shaft (a hand-cut tube on a cardboard cap),
  // so its top moves up and down (and along x) at the roller's frequency; 0 for true rollers.
  double runout = 0.0;  // m, both rollers
  // Rolling resistance: the lever arm delta by which each contact's pressure centre sits ahead of
  // the roller's surface motion (a soft tube); for inward rollers the contacts sit delta outward
  // of the tops, so the plate rests on contacts l + 2 delta apart (l - 2 delta outward). 0: rigid.
  double rolling_resistance = 0.0;  // m
  // Axes not quite parallel: roller 0's axis turned by +skew/2 about +z, roller 1's by -skew/2.
  // Their surfaces then move along +y too (inward rollers), and the plate drifts sideways. 0:
  // parallel.
  double skew = 0.0;                             // rad
  std::array<double, 2> runout_phase{0.0, 0.0};  // rad, where each tube's axis sits at t = 0
  std::string material = "pvc";
};

// Mass carried on the plate's top (LEGO blocks, modelling clay) that raises the centre of mass.
struct PayloadDesc {
  double mass = 0.0;    // kg
  double height = 0.0;  // m, of the payload's centre of mass above the plate's top face
  // m, of the payload's centre along the plate from the plate's middle (its spread unchanged):
  // the plate's centre of mass then lies off its middle.
  double x = 0.0;
};

// A LEGO block on the plate's top (the paper's blocks hold the magnets), its mass and centre of
// mass from the part index (assets/lego/parts.yaml), resolved when the scene is loaded.
struct PlateBlock {
  std::string part;     // "brick-2x4"
  double x = 0.0;       // m, of its centre along the plate from the plate's centre
  double y = 0.0;       // m, across the plate
  int turn = 0;         // degrees about z: 0, 90, 180, 270
  double mass = 0.0;    // kg
  double com_z = 0.0;   // m, its centre of mass above the plate's top face
  double height = 0.0;  // m, its body's height (studs not included): a magnet on top sits here
};

struct PlateDesc {
  double length = 0.200;       // m, along x
  double width = 0.060;        // m, along y
  double thickness = 0.005;    // m, along z
  std::optional<double> mass;  // kg of the slab; if absent, density x volume
  double density = 1050.0;     // kg/m^3 (ABS), used when mass is absent
  std::string material = "lego";
  PayloadDesc payload;
  std::vector<PlateBlock> blocks;
  double offset = 0.020;           // m, initial x of the plate's centre
  double velocity = 0.0;           // m/s, initial x velocity
  double sideways_velocity = 0.0;  // m/s, initial y velocity (a nudge toward the guides)
};

// A cylindrical magnet fixed on the plate's top face, magnetised along its axis (z).
struct MagnetDesc {
  double x = 0.0;            // m, of its centre, along the plate from the plate's centre
  double height = 0.0;       // m, of its bottom face above the plate's top face (on a block)
  double diameter = 0.006;   // m
  double thickness = 0.003;  // m
  double remanence = 1.2;    // T (N35 neodymium); negative flips the pole that faces up
  double density = 7500.0;   // kg/m^3 (NdFeB)
};

// A linear Hall sensor read by an ADC at its own clock.
struct SensorDesc {
  Vec3 position{0.07, 0.0, 0.012};  // m, world frame
  Vec3 axis{0.0, 0.0, 1.0};         // unit vector, the field component measured
  double sensitivity = 25.0;        // V/T (2.5 mV/G)
  double supply = 5.0;              // V, also the ADC's reference
  std::optional<double> offset;     // V at zero field; default supply / 2
  int adc_bits = 10;
  double sample_rate = 1000.0;  // Hz
  double noise = 0.002;         // V rms, white, added before the ADC
  double jitter = 10e-6;        // s rms, of each sample's time
  // The board's clock runs fast by this fraction (slow if negative), as a ceramic resonator does
  // (typically within +-0.5 %): its time stamps and its sampling both follow it.
  double clock_error = 0.0;
};

// A phone's sensor, recorded as phyphox records it (its CSV export): a magnetometer lying beside
// the rig, or an accelerometer lying on the plate, whose mass then counts in the plate's. The
// phone lies flat, screen up, its axes phyphox's: x to the screen's right, y toward its top, z out
// of the screen.
enum class PhoneSensor { kMagnetometer, kAccelerometer };

struct PhoneDesc {
  PhoneSensor sensor = PhoneSensor::kMagnetometer;
  double rate = 100.0;  // Hz, samples a second (by default 100 Hz magnetometer, 400 accelerometer)
  double noise = 0.2e-6;  // rms on each axis: T (magnetometer) or m/s^2 (accelerometer)
  // rad about +z from the rig's +x to the phone's top (its y axis): 0 lays its long side along
  // the plate's motion, its top toward +x.
  double turn = 0.0;
  // A magnetometer: where it is [m, world frame] and the Earth's field there [T, the rig's frame].
  Vec3 position{};
  Vec3 earth{21e-6, -4e-6, -43e-6};
  // An accelerometer on the plate: with g (phyphox's "Acceleration") or without it ("Linear
  // Acceleration"); where it lies on the plate and what it weighs.
  bool gravity = true;
  double x = 0.0;       // m, its centre along the plate from the plate's centre
  double height = 0.0;  // m, its bottom face above the plate's top face (on bricks: 9.6 mm)
  double mass = 0.180;  // kg
  Vec3 size{0.075, 0.150, 0.008};  // m: width (its x), length (its y), thickness (its z)
};

// A phone of `sensor` with its own defaults: a magnetometer at 100 Hz with 0.2 uT of noise, an
// accelerometer at 400 Hz with 0.05 m/s^2 (phyphox's rates, a phone's noise).
PhoneDesc phone_with(PhoneSensor sensor);

// Rollers that start cold (friction.temperature, e.g. 77 K after liquid nitrogen) and warm toward
// the room (core/roller_warming.hpp): mu_k follows their temperature, linear between its value
// at the start and at the room's temperature.
struct WarmingDesc {
  double room_temperature = 300.0;  // K
  // s. The PVC wall (1.5 mm, 1400 kg/m^3, c about 700 J/(kg K) averaged from 77 to 300 K) cooled
  // by the air over a tube turning at 1.7 m/s (h about 30 W/(m^2 K), a cylinder in cross-flow at
  // Re about 2300): tau = rho c w / h, about 50 s (docs/physics.md).
  double time_constant = 50.0;
  double hold = 0.0;  // s at the start temperature first (the nitrogen inside the tubes boiling)
  // mu_k at the room's temperature: the paper's 300 K value for the material when mu_k is taken
  // from the paper; otherwise the scene must give it.
  std::optional<double> mu_k_room;
};

struct FrictionDesc {
  // The law between plate and rollers (core/friction_law.hpp): coulomb (mu_k, and a static limit
  // mu_s) or stribeck (mu_k, mu_s, v_s, beta).
  FrictionLawKind law = FrictionLawKind::kCoulomb;
  // mu_k between plate and rollers. Empty `mu_k` with `from_paper` takes the paper's Table I
  // value for the plate's material at `temperature`.
  double mu_k = 0.29;
  std::optional<double> mu_s;  // the static limit, >= mu_k; absent: mu_k
  std::optional<double> v_s;   // m/s, the Stribeck speed (stribeck; needed when mu_s > mu_k)
  double beta = 0.0;           // s/m, the kinetic coefficient's slope (stribeck)
  bool from_paper = false;
  std::string paper_material;    // the Table I key used, when from_paper
  double temperature = 300.0;    // K (at the start, when the rollers warm)
  bool temperature_set = false;  // the scene named the temperature (videos show it then)
  std::optional<WarmingDesc> warming;
  // What the paper measured for that material and temperature, when from_paper.
  std::optional<Measured> paper_period;  // T +- dT [s]
  std::optional<Measured> paper_mu_k;

  // The rules a friction value keeps: mu_k positive, mu_s at least mu_k, a Stribeck law's v_s
  // when mu_s > mu_k and a finite beta, and, when the rollers' speeds are known to hold
  // (`speeds_hold`), mu(s) still positive at the run's largest slip speed [m/s]. Each broken rule
  // as the scene key responsible and what is wrong (scene_checks.cpp adds them to the scene's).
  std::vector<std::pair<std::string, Said>> problems(double largest_slip_speed,
                                                     bool speeds_hold) const;
};

// A 12 V DC motor with a linear torque-speed curve, its voltage set by PWM (the paper's Arduino).
struct MotorDesc {
  double rated_voltage = 12.0;                // V
  double no_load_speed = 20.943951023931955;  // rad/s at the rated voltage (200 rpm)
  double stall_torque = 0.8;                  // N m at the rated voltage
  double duty = 1.0;                          // PWM duty, 0 to 1
  // The duty over time instead (values 0 to 1, times in s): piecewise linear, held after its
  // last point. Empty: the constant `duty`.
  std::vector<RampPoint> duty_ramp;
  double inertia = 5e-4;  // kg m^2, rotor (~5e-7) through a ~30:1 gearhead, seen at the output
};

// One mesh of the gearbox: a driver gear turning a driven gear (tooth counts).
struct GearStage {
  int driver = 16;
  int driven = 8;
};

// LEGO spur gear data the physics needs, resolved from the part index when loaded.
struct GearSpec {
  int teeth = 0;
  double mass = 0.0;          // kg
  double inertia = 0.0;       // kg m^2 about its axis
  double pitch_radius = 0.0;  // m
};

// The rig's drive: the motor turns roller 0 through the gearbox's stages (speed-up 2:1 each in
// the paper's rig: 16 to 8 teeth); roller 0 turns roller 1 the other way through two idlers.
struct DriveDesc {
  MotorDesc motor;
  std::vector<GearStage> stages;  // motor -> roller 0; empty: the motor turns roller 0 directly
  int roller_gear = 24;           // on each roller's axle, at the rollers' far end
  int idler_gear = 40;            // two idlers between the roller gears
  std::vector<GearSpec> gears;    // every tooth count used, from the part index
  const GearSpec& gear(int teeth) const;
};

// A LEGO part of the frame, placed on the stud grid (resolved from the part index).
struct CollisionBoxDesc {
  Vec3 center{};  // m, in the part's frame
  Vec3 size{};    // m, full edges
};

struct FramePart {
  std::string part;                              // "technic-brick-1x16"
  std::array<int, 3> at{0, 0, 0};                // studs along x, studs along y, plates up
  int turn = 0;                                  // degrees about z: 0, 90, 180, 270
  std::array<float, 3> color{0.7f, 0.1f, 0.1f};  // sRGB
  bool guide = false;                            // collides with the plate (a guide tower's part)
  Vec3 position{};                               // m, the part's origin in the world
  std::vector<CollisionBoxDesc> boxes;           // its collision boxes (used when guide)
};

struct FrameDesc {
  Vec3 origin{0.0, 0.0, -0.03};  // m, where the stud grid's (0, 0, 0) sits in the world
  std::vector<FramePart> parts;
};

struct OutputDesc {
  bool trajectory = true;  // trajectory.csv with --out
  bool hall = true;        // hall.csv with --out (when the scene has a sensor)
  bool summary = true;     // summary.json with --out
  bool cycles = true;      // cycles.csv with --out (the plate's cycles, lab/run/cycle_report.hpp)
  bool periods = true;     // periods.csv with --out: each period the rig's estimator judged
  bool jumps = true;       // jumps.csv with --out, when the plate jumped
  bool phones = true;      // phone-magnetometer.csv, phone-accelerometer.csv (with phones)
};

struct Scene {
  std::string name;  // file stem or "inline"
  // A scene that explores a breakdown says which regime theory expects (oscillates, sticks,
  // tips, no restoring force, lost); the loader then lets set-ups through that it would
  // otherwise refuse (no restoring force, a plate too short), and the run diagnoses them.
  std::optional<Regime> expected_regime;
  WorldDesc world;
  RollersDesc rollers;
  PlateDesc plate;
  std::vector<MagnetDesc> magnets;
  std::optional<SensorDesc> sensor;
  std::vector<PhoneDesc> phones;  // phones' sensors, each writing its phyphox CSV
  FrictionDesc friction;
  std::optional<DriveDesc> drive;  // absent: the ideal drive (rollers.speed)
  std::optional<FrameDesc> frame;  // absent: no frame, no guides, no mesh
  OutputDesc output;
  std::optional<VideoDesc> video;  // how --video/--frames/--still draw it (video_yaml.hpp)
};

// The friction law the scene describes, as one value.
FrictionLaw friction_law(const FrictionDesc& friction);

// The largest slip speed a contact can see in a run [m/s]: the rollers' surface speed (without
// load) plus the plate's largest possible speed, which friction keeps below the surface speed
// unless the plate starts faster.
double largest_slip_speed(const Scene& scene);

// Mass properties of the plate as built (slab + payload + blocks + magnets).
struct PlateMass {
  double mass = 0.0;           // kg
  double x_c = 0.0;            // m, centre of mass along x from the plate's geometric centre
  double h_c = 0.0;            // m, centre of mass above the plate's bottom face (the contact line)
  double inertia_pitch = 0.0;  // kg m^2, about the y axis through the centre of mass
};
PlateMass plate_mass(const Scene& scene);

// The rollers' speed [rad/s] without load: rollers.speed for the ideal drive; for the motor
// drive, the duty's share of the motor's no-load speed times the gearbox's speed-up. For a scene
// that ramps the speed or the duty, the largest the ramp reaches (what bounds the run).
double nominal_roller_speed(const Scene& scene);

// The ramp a scene schedules (rollers.speed_ramp in rad/s for the ideal drive, or
// drive.motor.duty_ramp for the motor), or nullopt when its speed or duty is constant.
std::optional<Ramp> roller_speed_ramp(const Scene& scene);
// Roller 1's ramp: its own when the scene's ramp gives two speeds, else roller 0's (nullopt
// exactly when roller_speed_ramp is).
std::optional<Ramp> roller_speed_ramp_roller_1(const Scene& scene);
std::optional<Ramp> duty_ramp(const Scene& scene);

// The gearbox's speed-up from the motor to the rollers (product of driver / driven teeth).
double gearbox_ratio(const DriveDesc& drive);

}  // namespace fl
