#include "scene/scene_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "core/analytic_model.hpp"
#include "core/plausible_range.hpp"
#include "core/units.hpp"
#include "scene/drive_layout.hpp"
#include "text/describe.hpp"

namespace fl {
namespace {

bool finite_positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

// The checks' one record of problems, and the kinds of check the parts share.
class Checks {
 public:
  explicit Checks(std::vector<SceneProblem>& problems) : problems_(problems) {}

  // A problem, said in the catalogues' words (text/said.hpp).
  void need(bool ok, const char* key, const Said& message,
            std::vector<std::string> involves = {}) const {
    if (!ok) problems_.push_back({key, english(message), message, std::move(involves)});
  }
  // A value that must be positive, in its SI unit; a length also in millimetres, as a student
  // gives it.
  void positive(double v, const char* key, const char* unit = "") const {
    if (finite_positive(v)) return;
    if (std::string_view(unit) == "m" && std::isfinite(v))
      need(false, key,
           said("check-length-must-be-positive", {arg("value", v), arg("value_mm", v * 1e3)}));
    else if (unit[0] != '\0')
      need(false, key, said("check-must-be-positive-in", {arg("value", v), arg("unit", unit)}));
    else
      need(false, key, said("check-must-be-positive", {arg("value", v)}));
  }
  // Beyond any bench (core/plausible_range.hpp): a slip of the unit or the keyboard, refused
  // before it is computed with (a plain 89 is 89 m; 1e300 rpm).
  void plausible(double v, const PlausibleRange& range, const char* key) const {
    if (!std::isfinite(v) || v <= 0.0) return;  // the checks before and after say those
    if (std::optional<Said> why = implausible_said(v, range))
      need(false, key, said("check-implausible-value", {arg("why", std::move(*why))}));
  }
  // A ramp: times from 0 s, increasing; values from `least` to `most`.
  void ramp(const std::vector<RampPoint>& points, const char* key, double least, double most,
            const char* unit) const {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const RampPoint& p = points[i];
      need(std::isfinite(p.at) && p.at >= 0.0 && (i == 0 || p.at > points[i - 1].at), key,
           said("check-ramp-time", {arg("point", i), arg("time", p.at)}));
      need(std::isfinite(p.value) && p.value >= least && p.value <= most, key,
           said("check-ramp-value", {arg("point", i), arg("value", p.value), arg("unit", unit),
                                     arg("least", least), arg("most", most)}));
    }
  }
  std::size_t count() const { return problems_.size(); }

 private:
  std::vector<SceneProblem>& problems_;
};

// The magnet whose swept volume (over `amplitude` either side) holds `point`, if any.
std::optional<std::size_t> magnet_sweeping(const Scene& s, const Vec3& point, double amplitude) {
  const double top = s.plate.thickness;
  for (std::size_t i = 0; i < s.magnets.size(); ++i) {
    const MagnetDesc& m = s.magnets[i];
    const double r = 0.5 * m.diameter;
    const bool inside_x = std::fabs(point[0] - m.x) <= amplitude + r;
    const bool inside_y = std::fabs(point[1]) <= r;
    const double bottom = top + m.height;
    const bool inside_z = point[2] >= bottom && point[2] <= bottom + m.thickness;
    if (inside_x && inside_y && inside_z) return i;
  }
  return std::nullopt;
}

// The world: gravity, tilt, the step and the duration.
void check_world(const Scene& s, const Checks& c) {
  c.positive(s.world.gravity, "world.gravity", "m/s^2");
  // A rig tilted beyond 30 degrees is no bench's slip of the level; at 90 the rollers carry
  // nothing.
  c.need(std::isfinite(s.world.tilt) && std::fabs(s.world.tilt) <= kPi / 6.0, "world.tilt",
         said("check-tilt", {arg("degrees", s.world.tilt * 180.0 / kPi)}));
  c.positive(s.world.time_step, "world.time_step", "s");
  c.positive(s.world.duration, "world.duration", "s");
  c.need(s.world.solver_iterations >= 1 && s.world.solver_iterations <= 10000,
         "world.solver_iterations",
         said("check-solver-iterations", {arg("iterations", s.world.solver_iterations)}));
  // A step of a quarter period or more cannot follow the plate (omega dt >= pi / 2): the
  // thin plate's period, which any plate with a restoring force has at least roughly.
  if (finite_positive(s.world.time_step) && finite_positive(s.rollers.spacing) &&
      finite_positive(s.friction.mu_k) && finite_positive(s.world.gravity)) {
    const double quarter = 0.25 * period_thin(s.rollers.spacing, s.friction.mu_k, s.world.gravity);
    c.need(s.world.time_step < quarter, "world.time_step",
           said("check-step-resolves", {arg("quarter", quarter), arg("step", s.world.time_step)}),
           {"rollers.spacing", "friction.mu_k", "world.gravity"});
  }
  if (finite_positive(s.world.time_step) && finite_positive(s.world.duration))
    c.need(s.world.duration >= s.world.time_step, "world.duration",
           said("check-duration-one-step",
                {arg("step", s.world.time_step), arg("duration", s.world.duration)}));
  if (finite_positive(s.world.time_step) && finite_positive(s.world.duration))
    c.need(s.world.duration / s.world.time_step <= 1e9, "world.duration",
           said("check-duration-steps", {arg("steps", s.world.duration / s.world.time_step)}));
}

// The rollers' shape and mounting, and every value against the bench's ranges.
void check_roller_shape(const Scene& s, const Checks& c) {
  c.positive(s.rollers.spacing, "rollers.spacing", "m");
  c.positive(s.rollers.radius, "rollers.radius", "m");
  if (s.rollers.radius_roller_1) {
    c.positive(*s.rollers.radius_roller_1, "rollers.radius", "m");
    c.need(!s.drive, "rollers.radius", said("check-two-radii-drive"));
  }
  c.plausible(s.rollers.spacing, kSpacingRange, "rollers.spacing");
  c.plausible(s.rollers.radius, kRollerRadiusRange, "rollers.radius");
  if (s.rollers.radius_roller_1)
    c.plausible(*s.rollers.radius_roller_1, kRollerRadiusRange, "rollers.radius");
  c.plausible(s.rollers.speed, kRollerSpeedRange, "rollers.speed");
  c.plausible(s.friction.mu_k, kMuKRange, "friction.mu_k");
  c.plausible(s.world.gravity, kGravityRange, "world.gravity");
  c.need(std::isfinite(s.rollers.skew) && std::fabs(s.rollers.skew) <= kPi / 18.0, "rollers.skew",
         said("check-skew", {arg("degrees", s.rollers.skew * 180.0 / kPi)}));
  // Bounded by the smaller roller where the two differ.
  const double radius_least =
      std::min(s.rollers.radius, s.rollers.radius_roller_1.value_or(s.rollers.radius));
  c.need(std::isfinite(s.rollers.rolling_resistance) && s.rollers.rolling_resistance >= 0.0 &&
             s.rollers.rolling_resistance < 0.5 * radius_least,
         "rollers.rolling_resistance",
         said("check-rolling-resistance", {arg("half_radius_mm", 0.5e3 * radius_least),
                                           arg("found_mm", s.rollers.rolling_resistance * 1e3)}));
  c.need(std::isfinite(s.rollers.runout) && s.rollers.runout >= 0.0 &&
             s.rollers.runout < 0.5 * radius_least,
         "rollers.runout",
         said("check-runout", {arg("half_radius_mm", 0.5e3 * radius_least),
                               arg("found_mm", 1e3 * s.rollers.runout)}));
  for (const double phase : s.rollers.runout_phase)
    c.need(std::isfinite(phase), "rollers.runout_phase", said("check-angles-finite"));
  c.positive(s.rollers.length, "rollers.length", "m");
}

// Rollers warming from their start temperature.
void check_warming(const Scene& s, const Checks& c) {
  if (const std::optional<WarmingDesc>& w = s.friction.warming) {
    c.need(std::isfinite(w->room_temperature) && w->room_temperature > s.friction.temperature,
           "friction.warming.room",
           said("check-warming-room",
                {arg("start_k", s.friction.temperature), arg("room_k", w->room_temperature)}));
    c.positive(w->time_constant, "friction.warming.time_constant", "s");
    c.need(std::isfinite(w->hold) && w->hold >= 0.0, "friction.warming.hold",
           said("check-not-negative-in", {arg("value", w->hold), arg("unit", "s")}));
    if (w->mu_k_room) c.positive(*w->mu_k_room, "friction.warming.mu_k_room");
  }
}

// The rollers' speeds and ramps; whether the ramps hold (the largest speed is read only then).
bool check_roller_speeds(const Scene& s, const Checks& c) {
  c.need(std::isfinite(s.rollers.speed) && s.rollers.speed >= 0.0, "rollers.speed",
         said("check-speed-not-negative", {arg("speed", s.rollers.speed)}));
  if (const std::optional<double>& second = s.rollers.speed_roller_1) {
    c.need(std::isfinite(*second) && *second >= 0.0, "rollers.speed",
           said("check-speed-1-not-negative", {arg("speed", *second)}));
    if (std::isfinite(*second) && *second > 0.0)
      c.plausible(*second, kRollerSpeedRange, "rollers.speed");
    c.need(!s.drive, "rollers.speed", said("check-two-speeds-drive"));
    c.need(s.rollers.speed_ramp.empty(), "rollers.speed", said("check-two-speeds-ramp"));
  }
  const std::size_t before_ramps = c.count();
  c.ramp(s.rollers.speed_ramp, "rollers.speed_ramp", 0.0, std::numeric_limits<double>::max(),
         " rad/s");
  c.ramp(s.rollers.speed_ramp_roller_1, "rollers.speed_ramp", 0.0,
         std::numeric_limits<double>::max(), " rad/s");
  c.need(s.rollers.speed_ramp_roller_1.empty() ||
             (s.rollers.speed_ramp_roller_1.size() == s.rollers.speed_ramp.size() &&
              std::equal(s.rollers.speed_ramp.begin(), s.rollers.speed_ramp.end(),
                         s.rollers.speed_ramp_roller_1.begin(),
                         [](const RampPoint& a, const RampPoint& b) { return a.at == b.at; })),
         "rollers.speed_ramp", said("check-ramp-times-match"));
  c.need(s.rollers.speed_ramp.empty() || !s.drive, "rollers.speed_ramp",
         said("check-ramp-with-drive"));
  if (s.drive) c.ramp(s.drive->motor.duty_ramp, "drive.motor.duty_ramp", 0.0, 1.0, "");
  // The largest speed a ramp reaches is read (check_friction) only once the ramps hold.
  return c.count() == before_ramps;
}

// The plate, and room for it between the rollers.
void check_plate(const Scene& s, const Checks& c) {
  const double radius_1 = s.rollers.radius_roller_1.value_or(s.rollers.radius);
  if (finite_positive(s.rollers.spacing) && finite_positive(s.rollers.radius) &&
      finite_positive(radius_1))
    c.need(s.rollers.spacing > s.rollers.radius + radius_1, "rollers.spacing",
           said("check-rollers-overlap", {arg("spacing_mm", s.rollers.spacing * 1e3),
                                          arg("radii_mm", 1e3 * (s.rollers.radius + radius_1))}));
  c.positive(s.plate.length, "plate.length", "m");
  c.positive(s.plate.width, "plate.width", "m");
  c.positive(s.plate.thickness, "plate.thickness", "m");
  if (s.plate.mass)
    c.positive(*s.plate.mass, "plate.mass", "kg");
  else
    c.positive(s.plate.density, "plate.density", "kg/m^3");
  c.need(std::isfinite(s.plate.payload.mass) && s.plate.payload.mass >= 0.0, "plate.payload.mass",
         said("check-not-negative-in", {arg("value", s.plate.payload.mass), arg("unit", "kg")}));
  c.need(std::isfinite(s.plate.payload.height) && s.plate.payload.height >= 0.0,
         "plate.payload.height",
         said("check-not-negative-in", {arg("value", s.plate.payload.height), arg("unit", "m")}));
  c.need(std::isfinite(s.plate.payload.x) && std::fabs(s.plate.payload.x) <= 0.5 * s.plate.length,
         "plate.payload.x",
         said("check-payload-on-plate", {arg("half_length_mm", 0.5e3 * s.plate.length),
                                         arg("x_mm", s.plate.payload.x * 1e3)}));
  c.need(std::isfinite(s.plate.offset), "plate.offset", said("check-must-be-finite"));
  c.need(std::isfinite(s.plate.velocity), "plate.velocity", said("check-must-be-finite"));
}

// The friction law: the rules the friction value keeps (FrictionDesc::problems).
void check_friction(const Scene& s, const Checks& c, bool ramps_hold) {
  const double s_max =
      ramps_hold && s.friction.law == FrictionLawKind::kStribeck ? largest_slip_speed(s) : 0.0;
  for (const auto& [key, message] : s.friction.problems(s_max, ramps_hold))
    c.need(false, key.c_str(), message);
}

// The magnets on the plate.
void check_magnets(const Scene& s, const Checks& c) {
  for (std::size_t i = 0; i < s.magnets.size(); ++i) {
    const MagnetDesc& m = s.magnets[i];
    c.need(
        finite_positive(m.diameter) && finite_positive(m.thickness) && finite_positive(m.density),
        "magnets", said("check-magnet-size", {arg("magnet", i)}));
    c.need(std::isfinite(m.remanence) && m.remanence != 0.0, "magnets",
           said("check-magnet-remanence", {arg("magnet", i)}));
    c.need(std::fabs(m.x) + 0.5 * m.diameter <= 0.5 * s.plate.length + 1e-12, "magnets",
           said("check-magnet-on-plate", {arg("magnet", i), arg("x_mm", m.x * 1e3),
                                          arg("half_length_mm", 0.5e3 * s.plate.length)}));
  }
}

// The set-up as a whole: an oscillation exists, and the plate stays on the rollers over its
// amplitude, which it returns (none when no oscillation exists, which is said).
std::optional<double> check_motion(const Scene& s, const Checks& c) {
  const PlateMass pm = plate_mass(s);
  const double l = s.rollers.spacing;
  const double mu = s.friction.mu_k;
  // A scene that explores a breakdown on purpose (expect.regime) is simulated and diagnosed.
  const bool exploring = s.expected_regime.has_value();
  if (!has_restoring_force(l, mu, pm.h_c) && !exploring) {
    c.need(false, "rollers.spacing",
           said("check-no-oscillation",
                {arg("spacing_mm", l * 1e3), arg("limit_mm", 2e3 * mu * pm.h_c), arg("mu_k", mu),
                 arg("h_c_mm", pm.h_c * 1e3)}));
    return std::nullopt;
  }
  const double amplitude =
      has_restoring_force(l, mu, pm.h_c)
          ? amplitude_from_start(s.plate.offset, s.plate.velocity,
                                 angular_frequency(l, mu, pm.h_c, s.world.gravity))
          : std::fabs(s.plate.offset);
  c.need(exploring || 0.5 * s.plate.length > 0.5 * l + amplitude, "plate.length",
         said("check-plate-too-short", {arg("length_mm", s.plate.length * 1e3),
                                        arg("needed_mm", (l + 2.0 * amplitude) * 1e3)}),
         {"rollers.spacing", "plate.offset", "plate.velocity"});
  return amplitude;
}

// The drive's gear train can be laid out.
void check_drive(const Scene& s, const Checks& c) {
  if (s.drive) {
    // The spacing is what a student changes; the gears are the scene's: the problem is the
    // spacing's, saying which gears bound it.
    if (std::optional<Said> why = drive_coupling_problem(s)) c.need(false, "rollers.spacing", *why);
  }
}

// The Hall sensor: its electronics, and a place the magnets never sweep over `amplitude`.
void check_sensor(const Scene& s, const Checks& c, double amplitude) {
  if (s.sensor) {
    const SensorDesc& sensor = *s.sensor;
    const double norm = std::hypot(sensor.axis[0], sensor.axis[1], sensor.axis[2]);
    c.need(std::isfinite(norm) && norm > 0.0, "sensor.axis", said("check-axis-non-zero"));
    c.positive(sensor.sensitivity, "sensor.sensitivity", "V/T");
    c.positive(sensor.supply, "sensor.supply", "V");
    c.positive(sensor.sample_rate, "sensor.sample_rate", "Hz");
    c.need(sensor.adc_bits >= 1 && sensor.adc_bits <= 16, "sensor.adc_bits",
           said("check-adc-bits", {arg("bits", sensor.adc_bits)}));
    c.need(std::isfinite(sensor.noise) && sensor.noise >= 0.0, "sensor.noise",
           said("check-not-negative", {arg("value", sensor.noise)}));
    c.need(std::isfinite(sensor.jitter) && sensor.jitter >= 0.0 &&
               sensor.jitter < 0.25 / sensor.sample_rate,
           "sensor.jitter", said("check-jitter"));
    c.need(std::isfinite(sensor.clock_error) && std::fabs(sensor.clock_error) < 0.1,
           "sensor.clock_error", said("check-clock-error", {arg("error", sensor.clock_error)}));
    if (sensor.offset)
      c.need(*sensor.offset >= 0.0 && *sensor.offset <= sensor.supply, "sensor.offset",
             said("check-sensor-offset"));
    c.need(sensor.position[2] > 0.0, "sensor.position", said("check-sensor-above"));
    // The sensor must not be inside the volume any magnet sweeps.
    if (const std::optional<std::size_t> i = magnet_sweeping(s, sensor.position, amplitude)) {
      const MagnetDesc& m = s.magnets[*i];
      c.need(false, "sensor.position",
             said("check-sensor-in-magnet-path",
                  {arg("magnet", *i),
                   arg("top_mm", (s.plate.thickness + m.height + m.thickness) * 1e3)}),
             {"plate.offset", "plate.velocity", "rollers.spacing"});
    }
  }
}

// The phones: their sampling, a magnetometer's field and place, an accelerometer's mass, size
// and place on the plate (what the plate's mass needs, so checked before the motion).
void check_phones(const Scene& s, const Checks& c) {
  for (std::size_t i = 0; i < s.phones.size(); ++i) {
    const PhoneDesc& p = s.phones[i];
    c.need(std::isfinite(p.rate) && p.rate >= 1.0 && p.rate <= 10000.0, "phones",
           said("check-phone-rate", {arg("phone", i), arg("rate", p.rate)}));
    c.need(std::isfinite(p.noise) && p.noise >= 0.0, "phones",
           said("check-phone-noise", {arg("phone", i), arg("noise", p.noise)}));
    c.need(std::isfinite(p.turn), "phones", said("check-phone-turn", {arg("phone", i)}));
    if (p.sensor == PhoneSensor::kMagnetometer) {
      const double earth = std::hypot(p.earth[0], p.earth[1], p.earth[2]);
      c.need(std::isfinite(earth) && earth <= 1e-3, "phones",
             said("check-phone-earth-field", {arg("phone", i), arg("field_ut", earth * 1e6)}));
      c.need(std::isfinite(p.position[0]) && std::isfinite(p.position[1]) &&
                 std::isfinite(p.position[2]),
             "phones", said("check-phone-position", {arg("phone", i)}));
      continue;
    }
    c.need(finite_positive(p.mass), "phones",
           said("check-phone-mass", {arg("phone", i), arg("mass_kg", p.mass)}));
    c.need(finite_positive(p.size[0]) && finite_positive(p.size[1]) && finite_positive(p.size[2]),
           "phones", said("check-phone-size", {arg("phone", i)}));
    c.need(std::isfinite(p.height) && p.height >= 0.0, "phones",
           said("check-phone-height", {arg("phone", i), arg("height_mm", p.height * 1e3)}));
    c.need(std::isfinite(p.x) && std::fabs(p.x) <= 0.5 * s.plate.length, "phones",
           said("check-phone-on-plate", {arg("phone", i), arg("x_mm", p.x * 1e3),
                                         arg("half_length_mm", 0.5e3 * s.plate.length)}));
  }
}

// A phone's magnetometer lies outside what the plate and its magnets sweep over `amplitude`.
void check_magnetometer_places(const Scene& s, const Checks& c, double amplitude) {
  for (std::size_t i = 0; i < s.phones.size(); ++i) {
    const PhoneDesc& p = s.phones[i];
    if (p.sensor != PhoneSensor::kMagnetometer) continue;
    const Vec3& at = p.position;
    const bool in_slab = std::fabs(at[0]) <= 0.5 * s.plate.length + amplitude &&
                         std::fabs(at[1]) <= 0.5 * s.plate.width && at[2] >= 0.0 &&
                         at[2] <= s.plate.thickness;
    c.need(!in_slab, "phones",
           said("check-magnetometer-in-plate-path",
                {arg("phone", i), arg("x_mm", at[0] * 1e3), arg("y_mm", at[1] * 1e3),
                 arg("z_mm", at[2] * 1e3), arg("half_width_mm", 0.5e3 * s.plate.width)}),
           {"plate.offset", "plate.velocity"});
    if (const std::optional<std::size_t> m = magnet_sweeping(s, at, amplitude))
      c.need(false, "phones",
             said("check-magnetometer-in-magnet-path", {arg("phone", i), arg("magnet", *m)}),
             {"plate.offset", "plate.velocity"});
  }
}

}  // namespace

std::vector<SceneProblem> check_scene(const Scene& s) {
  std::vector<SceneProblem> problems;
  const Checks c(problems);
  check_world(s, c);
  check_roller_shape(s, c);
  check_warming(s, c);
  const bool ramps_hold = check_roller_speeds(s, c);
  check_plate(s, c);
  check_friction(s, c, ramps_hold);
  check_magnets(s, c);
  check_phones(s, c);
  if (!problems.empty()) return problems;
  // The physics of the set-up as a whole.
  const std::optional<double> amplitude = check_motion(s, c);
  if (!amplitude) return problems;
  check_drive(s, c);
  check_sensor(s, c, *amplitude);
  check_magnetometer_places(s, c, *amplitude);
  return problems;
}

}  // namespace fl
