#include "physics/drivetrain.hpp"

#include <cmath>
#include <numbers>

namespace fl {

Drivetrain::Drivetrain(const Scene& scene)
    : layout_(drive_layout(scene)), motor_(scene.drive.value().motor) {
  const DriveDesc& drive = scene.drive.value();
  const std::size_t n = layout_.shafts.size();
  // Each shaft's speed over the motor's, mesh by mesh from the motor.
  ratios_.assign(n, 0.0);
  ratios_[static_cast<std::size_t>(layout_.motor)] = 1.0;
  for (const GearMesh& m : layout_.meshes) {
    const GearPlacement& a = layout_.gears[static_cast<std::size_t>(m.driver)];
    const GearPlacement& b = layout_.gears[static_cast<std::size_t>(m.driven)];
    ratios_[static_cast<std::size_t>(b.shaft)] =
        -ratios_[static_cast<std::size_t>(a.shaft)] * a.teeth / b.teeth;
  }
  // Each shaft's moment of inertia about its axis: its gears, the motor, the roller's tube;
  // the train's, seen at the motor: sum I_k u_k^2.
  std::vector<double> inertia(n, 0.0);
  for (const GearPlacement& g : layout_.gears)
    inertia[static_cast<std::size_t>(g.shaft)] += drive.gear(g.teeth).inertia;
  inertia[static_cast<std::size_t>(layout_.motor)] += motor_.inertia;
  const RollersDesc& r = scene.rollers;
  const double inner = std::max(0.0, r.radius - r.wall);
  const double tube =
      r.density * std::numbers::pi * (r.radius * r.radius - inner * inner) * r.length;
  for (std::size_t i = 0; i < 2; ++i)
    inertia[i] += 0.5 * tube * (r.radius * r.radius + inner * inner);
  for (std::size_t k = 0; k < n; ++k) inertia_ += inertia[k] * ratios_[k] * ratios_[k];

  // The motor turns the way that makes roller 0's top move toward the centre (inward) or away.
  const double roller0 = scene.rollers.sense == RollerSense::kInward ? 1.0 : -1.0;
  sign_ = ratios_[0] > 0.0 ? roller0 : -roller0;
  // The train starts at its no-load speed for the duty.
  omega_ = sign_ * motor_.duty * motor_.no_load_speed;
}

void Drivetrain::advance(double dt, const std::array<double, 2>& roller_torques) {
  const double c = motor_.stall_torque / motor_.no_load_speed;
  // The load, seen at the motor (power balance: tau_motor omega_m = tau_roller omega_roller).
  const double load = ratios_[0] * roller_torques[0] + ratios_[1] * roller_torques[1];
  // J (omega' - omega) / dt = s duty tau_stall - c omega' + load   (the damper at the new speed)
  const double drive = sign_ * motor_.duty * motor_.stall_torque;
  const double next = (inertia_ * omega_ + dt * (drive + load)) / (inertia_ + dt * c);
  motor_torque_ = sign_ * (drive - c * next);
  omega_ = next;
  theta_ += omega_ * dt;
}

double Drivetrain::speed(int shaft) const {
  return ratios_[static_cast<std::size_t>(shaft)] * omega_;
}
double Drivetrain::angle(int shaft) const {
  return ratios_[static_cast<std::size_t>(shaft)] * theta_;
}

}  // namespace fl
