#include "scene/compiled_rig.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/friction_oscillator.hpp"
#include "core/integrator_error.hpp"
#include "core/skewed_rollers.hpp"
#include "core/tilted_rig.hpp"
#include "core/unequal_radii.hpp"
#include "core/units.hpp"

namespace fl {
namespace {

CompiledDrive compile_drive(const Scene& scene, const PlateMass& plate, double mu_k) {
  const DriveDesc& drive = scene.drive.value();
  CompiledDrive out;
  out.parts = drive;
  out.layout = drive_layout(scene);
  const DriveLayout& layout = out.layout;
  const std::size_t n = layout.shafts.size();
  // Each shaft's speed over the motor's, mesh by mesh from the motor.
  out.shaft_ratios.assign(n, 0.0);
  out.shaft_ratios[static_cast<std::size_t>(layout.motor)] = 1.0;
  for (const GearMesh& m : layout.meshes) {
    const GearPlacement& a = layout.gears[static_cast<std::size_t>(m.driver)];
    const GearPlacement& b = layout.gears[static_cast<std::size_t>(m.driven)];
    out.shaft_ratios[static_cast<std::size_t>(b.shaft)] =
        -out.shaft_ratios[static_cast<std::size_t>(a.shaft)] * a.teeth / b.teeth;
  }
  out.gearbox_ratio = gearbox_ratio(drive);
  // Each shaft's moment of inertia about its axis: its gears, the motor, the roller's tube;
  // the train's, seen at the motor: sum I_k u_k^2.
  std::vector<double> inertia(n, 0.0);
  for (const GearPlacement& g : layout.gears)
    inertia[static_cast<std::size_t>(g.shaft)] += drive.gear(g.teeth).inertia;
  inertia[static_cast<std::size_t>(layout.motor)] += drive.motor.inertia;
  const RollersDesc& r = scene.rollers;
  const double inner = std::max(0.0, r.radius - r.wall);
  const double tube = r.density * kPi * (r.radius * r.radius - inner * inner) * r.length;
  for (std::size_t i = 0; i < 2; ++i)
    inertia[i] += 0.5 * tube * (r.radius * r.radius + inner * inner);
  for (std::size_t k = 0; k < n; ++k)
    out.inertia_at_motor += inertia[k] * out.shaft_ratios[k] * out.shaft_ratios[k];
  // The motor turns the way that makes roller 0's top move toward the centre (inward) or away.
  const double roller0 = scene.rollers.sense == RollerSense::kInward ? 1.0 : -1.0;
  out.motor_sense = out.shaft_ratios[0] > 0.0 ? roller0 : -roller0;

  // Both rollers slip against the plate, taking mu_k m g a between them, G times that at the
  // motor; on the linear curve the motor keeps duty - load / stall of its no-load speed.
  const MotorDesc& motor = drive.motor;
  out.stall_load_torque = mu_k * plate.mass *
                          gravity_normal(scene.world.gravity, scene.world.tilt) * r.radius *
                          out.gearbox_ratio;
  const auto ramp = duty_ramp(scene);
  const double duty = ramp ? ramp->smallest() : motor.duty;
  const double share = duty - out.stall_load_torque / motor.stall_torque;
  if (share > 0.0) out.roller_speed_loaded = out.gearbox_ratio * motor.no_load_speed * share;
  return out;
}

// How far apart the plate's contacts are: along the line through the rollers' tops, which
// rollers of different radii tilt (core/unequal_radii.hpp), the tangent points lie l cos(tilt)
// apart, and rolling resistance moves each contact delta outward of its tangent point (inward
// rollers) or inward (scene.hpp).
double contact_spacing(const Scene& scene, const std::array<double, 2>& radii) {
  const double delta = scene.rollers.rolling_resistance;
  return tangent_spacing(scene.rollers.spacing, radii[0], radii[1]) +
         (scene.rollers.sense == RollerSense::kInward ? 2.0 * delta : -2.0 * delta);
}

// The run's guards from the rig (before it takes the scene).
CompiledRig::RunGuards run_guards(const CompiledRig& rig, const Scene& scene) {
  CompiledRig::RunGuards g;
  const double plate_mass = rig.plate.mass;
  const double a_min = std::min(rig.roller_radii[0], rig.roller_radii[1]);
  const double a_max = std::max(rig.roller_radii[0], rig.roller_radii[1]);
  g.surface_speed = rig.roller_speed_nominal * a_max;
  const double v = std::max(g.surface_speed, std::fabs(scene.plate.velocity));
  g.energy = 10.0 * (0.5 * plate_mass * v * v +
                     plate_mass * scene.world.gravity * (scene.plate.length + a_max));
  g.penetration = std::min(0.5e-3, 0.1 * a_min);
  g.speed = 2.0 * v + 0.5;
  g.turn = rig.roller_speed_nominal > 0.0 ? 2.0 * kPi / rig.roller_speed_nominal : 0.0;
  if (rig.friction.depends_on_slip() && rig.restoring) {
    try {
      g.linearised_growth =
          linearised_motion(rig.friction, {rig.contact_spacing, rig.plate.h_c, rig.gravity_normal},
                            g.surface_speed)
              .gamma;
    } catch (const DomainError&) {
      g.linearised_growth.reset();
    }
  }
  return g;
}

FrictionSource friction_source(const FrictionDesc& f) {
  FrictionSource out;
  if (f.from_paper) {
    out.paper_material = f.paper_material;
    out.paper_period = f.paper_period;
    out.paper_mu_k = f.paper_mu_k;
  }
  out.temperature = f.temperature;
  out.temperature_set = f.temperature_set;
  return out;
}

}  // namespace

CompiledRig compile_rig(Scene scene) {
  CompiledRig rig;
  rig.plate = plate_mass(scene);
  rig.friction = friction_law(scene.friction);
  if (const std::optional<WarmingDesc>& w = scene.friction.warming)
    rig.warming.emplace(scene.friction.temperature, w->room_temperature, w->time_constant, w->hold,
                        rig.friction.mu_k, w->mu_k_room.value_or(rig.friction.mu_k));
  rig.roller_speed_nominal = nominal_roller_speed(scene);
  rig.roller_speed_ramp = roller_speed_ramp(scene);
  rig.roller_speed_ramp_roller_1 = roller_speed_ramp_roller_1(scene);
  rig.duty_ramp = duty_ramp(scene);
  if (scene.drive) rig.drive = compile_drive(scene, rig.plate, rig.friction.mu_k);

  rig.roller_radii = {scene.rollers.radius,
                      scene.rollers.radius_roller_1.value_or(scene.rollers.radius)};
  const std::array<double, 2>& radii = rig.roller_radii;
  const double l = contact_spacing(scene, radii), mu = rig.friction.mu_k, h_c = rig.plate.h_c,
               tilt = scene.world.tilt + tangent_tilt(scene.rollers.spacing, radii[0], radii[1]);
  rig.contact_spacing = l;
  rig.contact_tilt = tilt;
  const double g = gravity_normal(scene.world.gravity, tilt);
  rig.gravity_normal = g;
  rig.period_thin = period_thin(l, mu, g);
  rig.restoring = has_restoring_force(l, mu, h_c);
  rig.amplitude_initial = std::fabs(scene.plate.offset);
  if (rig.restoring) {
    // Each roller's coefficient at its own surface speed (rollers at different speeds under a
    // slip-speed law put the centre off the midpoint; coulomb's is mu_k at any speed).
    // A ramp with a speed for each roller: theory's centre at its first point's speeds.
    const bool own_speeds =
        (scene.rollers.speed_roller_1 || !scene.rollers.speed_ramp_roller_1.empty()) &&
        !scene.drive;
    const double speed_0 =
        rig.roller_speed_ramp ? rig.roller_speed_ramp->at(0.0) : scene.rollers.speed;
    const double speed_1 = rig.roller_speed_ramp_roller_1
                               ? rig.roller_speed_ramp_roller_1->at(0.0)
                               : scene.rollers.speed_roller_1.value_or(speed_0);
    const bool own_surfaces = own_speeds || radii[0] != radii[1];
    const double mu_0 = own_surfaces ? rig.friction.kinetic(speed_0 * radii[0]) : mu;
    const double mu_1 = own_surfaces ? rig.friction.kinetic(speed_1 * radii[1]) : mu;
    try {
      rig.oscillation_centre = oscillation_centre(l, mu_0, mu_1, h_c, tilt);
    } catch (const DomainError&) {  // the two coefficients together leave no restoring force
      rig.oscillation_centre = oscillation_centre(l, mu, h_c, tilt);
    }
    rig.period_thick = period_thick(l, mu, h_c, g);
    rig.omega = 2.0 * kPi / *rig.period_thick;
    rig.integrator_bias = integrator_period_bias(*rig.omega, scene.world.time_step);
    rig.conditioning = mu_k_with_uncertainty(*rig.period_thick, 0.0, l, 0.0, h_c, g);
    rig.amplitude_initial = amplitude_from_start(scene.plate.offset - *rig.oscillation_centre,
                                                 scene.plate.velocity, *rig.omega);
    rig.tipping_amplitude = tipping_amplitude(l, mu, h_c) - std::fabs(*rig.oscillation_centre);
    rig.slip_threshold = roller_speed_for_full_slip(rig.amplitude_initial,
                                                    std::min(radii[0], radii[1]), l, mu, h_c, g);
  }
  if (h_c > 0.0) rig.mu_k_restoring_limit = l / (2.0 * h_c);
  // Skewed axes: both surfaces move along +y at v_r sin(skew / 2); the plate's slip along y dies
  // out and it drifts with them (docs/physics.md). One surface speed for both rollers only.
  const bool one_speed =
      !rig.roller_speed_ramp && radii[0] == radii[1] &&
      !(scene.rollers.speed_roller_1 && *scene.rollers.speed_roller_1 != scene.rollers.speed);
  bool guided = false;  // guide towers stop the drift where the plate meets one
  if (scene.frame)
    for (const FramePart& part : scene.frame->parts) guided = guided || part.guide;
  // The rollers' speed: the set one, or the motor's under the plate's load (none if it stalls).
  const std::optional<double> speed =
      rig.drive ? rig.drive->roller_speed_loaded : std::optional<double>(scene.rollers.speed);
  if (scene.rollers.skew != 0.0 && one_speed && !guided && speed)
    rig.drift_speed = skew_drift_speed(*speed * radii[0], scene.rollers.skew);
  rig.guards = run_guards(rig, scene);
  rig.name = std::move(scene.name);
  rig.world = scene.world;
  rig.rollers = std::move(scene.rollers);
  rig.plate_desc = std::move(scene.plate);
  rig.magnets = std::move(scene.magnets);
  rig.sensor = std::move(scene.sensor);
  rig.phones = std::move(scene.phones);
  rig.frame = std::move(scene.frame);
  rig.friction_source = friction_source(scene.friction);
  return rig;
}

CompiledRig with_time_step(CompiledRig rig, double time_step) {
  rig.world.time_step = time_step;
  if (rig.omega) rig.integrator_bias = integrator_period_bias(*rig.omega, time_step);
  return rig;
}

CompiledRig with_solver_iterations(CompiledRig rig, int iterations) {
  rig.world.solver_iterations = iterations;
  return rig;
}

std::shared_ptr<const CompiledRig> compile_rig_shared(Scene scene) {
  return std::make_shared<const CompiledRig>(compile_rig(std::move(scene)));
}

}  // namespace fl
