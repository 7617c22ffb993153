#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/analytic_model.hpp"
#include "core/units.hpp"
#include "text/describe.hpp"

namespace fl {

PlateMass plate_mass(const Scene& scene) {
  const PlateDesc& p = scene.plate;
  const double slab = p.mass ? *p.mass : p.density * p.length * p.width * p.thickness;
  // Parts: mass, centre (x, z) with z above the plate's bottom face, own pitch inertia.
  struct Part {
    double m, x, z, own;
  };
  std::vector<Part> parts;
  parts.push_back({slab, 0.0, 0.5 * p.thickness,
                   slab * (p.length * p.length + p.thickness * p.thickness) / 12.0});
  // The payload is spread evenly along the plate (the paper's LEGO blocks keep the mass uniform),
  // its centre at payload.x.
  if (p.payload.mass > 0.0)
    parts.push_back({p.payload.mass, p.payload.x, p.thickness + p.payload.height,
                     p.payload.mass * p.length * p.length / 12.0});
  for (const PlateBlock& block : p.blocks) {
    // A block's own pitch inertia is small against the plate's; it counts as a point mass.
    parts.push_back({block.mass, block.x, p.thickness + block.com_z, 0.0});
  }
  for (const MagnetDesc& magnet : scene.magnets) {
    const double r = 0.5 * magnet.diameter;
    const double m = magnet.density * kPi * r * r * magnet.thickness;
    parts.push_back({m, magnet.x, p.thickness + magnet.height + 0.5 * magnet.thickness,
                     m * (3.0 * r * r + magnet.thickness * magnet.thickness) / 12.0});
  }
  // A phone lying on the plate: a uniform box, its extent along x as it is turned.
  for (const PhoneDesc& phone : scene.phones) {
    if (phone.sensor != PhoneSensor::kAccelerometer) continue;
    const double along = std::fabs(phone.size[0] * std::sin(phone.turn)) +
                         std::fabs(phone.size[1] * std::cos(phone.turn));
    const double t = phone.size[2];
    parts.push_back({phone.mass, phone.x, p.thickness + phone.height + 0.5 * t,
                     phone.mass * (along * along + t * t) / 12.0});
  }
  PlateMass out;
  double mx = 0.0, mz = 0.0;
  for (const Part& part : parts) {
    out.mass += part.m;
    mx += part.m * part.x;
    mz += part.m * part.z;
  }
  const double cx = mx / out.mass;
  out.x_c = cx;
  out.h_c = mz / out.mass;
  for (const Part& part : parts) {
    const double dx = part.x - cx;
    const double dz = part.z - out.h_c;
    out.inertia_pitch += part.own + part.m * (dx * dx + dz * dz);
  }
  return out;
}

PhoneDesc phone_with(PhoneSensor sensor) {
  PhoneDesc p;
  p.sensor = sensor;
  if (sensor == PhoneSensor::kAccelerometer) {
    p.rate = 400.0;
    p.noise = 0.05;
  }
  return p;
}

FrictionLaw friction_law(const FrictionDesc& f) {
  FrictionLaw law;
  law.kind = f.law;
  law.mu_k = f.mu_k;
  law.mu_s = f.mu_s.value_or(f.mu_k);
  law.v_s = f.v_s.value_or(0.0);
  law.beta = f.beta;
  return law;
}

double largest_slip_speed(const Scene& scene) {
  const double surface =
      nominal_roller_speed(scene) *
      std::max(scene.rollers.radius, scene.rollers.radius_roller_1.value_or(0.0));
  return surface + std::max(surface, std::fabs(scene.plate.velocity));
}

const GearSpec& DriveDesc::gear(int teeth) const {
  for (const GearSpec& g : gears)
    if (g.teeth == teeth) return g;
  throw std::out_of_range("no " + std::to_string(teeth) + "-tooth gear in the drive's gear list");
}

double gearbox_ratio(const DriveDesc& drive) {
  double ratio = 1.0;
  for (const GearStage& st : drive.stages) ratio *= static_cast<double>(st.driver) / st.driven;
  return ratio;
}

double nominal_roller_speed(const Scene& scene) {
  if (!scene.drive) {
    if (const auto ramp = roller_speed_ramp(scene)) return ramp->largest();
    return std::max(scene.rollers.speed, scene.rollers.speed_roller_1.value_or(0.0));
  }
  const auto ramp = duty_ramp(scene);
  const double duty = ramp ? ramp->largest() : scene.drive->motor.duty;
  return duty * scene.drive->motor.no_load_speed * gearbox_ratio(*scene.drive);
}

std::optional<Ramp> roller_speed_ramp(const Scene& scene) {
  if (scene.drive || scene.rollers.speed_ramp.empty()) return std::nullopt;
  return Ramp(scene.rollers.speed_ramp);
}

std::optional<Ramp> roller_speed_ramp_roller_1(const Scene& scene) {
  if (scene.rollers.speed_ramp_roller_1.empty()) return roller_speed_ramp(scene);
  if (scene.drive) return std::nullopt;
  return Ramp(scene.rollers.speed_ramp_roller_1);
}

std::optional<Ramp> duty_ramp(const Scene& scene) {
  if (!scene.drive || scene.drive->motor.duty_ramp.empty()) return std::nullopt;
  return Ramp(scene.drive->motor.duty_ramp);
}

std::vector<std::pair<std::string, Said>> FrictionDesc::problems(double largest_slip_speed,
                                                                 bool speeds_hold) const {
  std::vector<std::pair<std::string, Said>> out;
  const auto need = [&](bool ok, const char* key, Said message) {
    if (!ok) out.emplace_back(key, std::move(message));
  };
  need(std::isfinite(mu_k) && mu_k > 0.0, "friction.mu_k",
       said("check-mu-k-positive", {arg("mu_k", mu_k)}));
  if (mu_s)
    need(std::isfinite(*mu_s) && *mu_s >= mu_k, "friction.mu_s",
         said("check-mu-s-at-least-mu-k", {arg("mu_k", mu_k), arg("mu_s", *mu_s)}));
  if (law != FrictionLawKind::kStribeck) return out;
  need(!(mu_s && *mu_s > mu_k) || v_s.has_value(), "friction.mu_s", said("check-stribeck-v-s"));
  need(std::isfinite(beta), "friction.beta", said("check-beta-finite", {arg("beta", beta)}));
  // mu(s) falls monotonically when beta < 0: its least value is at the largest slip speed.
  const double mu_min = friction_law(*this).kinetic(largest_slip_speed);
  need(!speeds_hold || beta >= 0.0 || mu_min > 0.0, "friction.beta",
       said("check-mu-negative", {arg("mu_min", mu_min), arg("slip_speed", largest_slip_speed)}));
  return out;
}

}  // namespace fl
