#include "physics/drivetrain.hpp"

#include <cmath>

namespace fl {

Drivetrain::Drivetrain(const CompiledRig& rig)
    : drive_(rig.drive.value()), motor_(rig.drive.value().parts.motor) {
  // The train starts at its no-load speed for the duty.
  const double duty = rig.duty_ramp ? rig.duty_ramp->at(0.0) : motor_.duty;
  omega_ = drive_.motor_sense * duty * motor_.no_load_speed;
}

void Drivetrain::advance(double dt, const std::array<double, 2>& roller_torques, double duty,
                         double holding_torque) {
  const double c = motor_.stall_torque / motor_.no_load_speed;
  // The load, seen at the motor (power balance: tau_motor omega_m = tau_roller omega_roller).
  const std::vector<double>& u = drive_.shaft_ratios;
  const double load = u[0] * roller_torques[0] + u[1] * roller_torques[1];
  // J (omega' - omega) / dt = s duty tau_stall - c omega' + load   (the damper at the new speed)
  const double sign = drive_.motor_sense;
  const double inertia = drive_.inertia_at_motor;
  const double drive = sign * duty * motor_.stall_torque;
  if (omega_ == 0.0 && std::fabs(drive) <= holding_torque) {
    // Held at rest by the plate's static friction: the motor stalls.
    motor_torque_ = sign * drive;
    return;
  }
  double next = (inertia * omega_ + dt * (drive + load)) / (inertia + dt * c);
  // Friction that brings the train to rest within the step stops it there.
  if (omega_ != 0.0 && next * omega_ < 0.0) next = 0.0;
  motor_torque_ = sign * (drive - c * next);
  omega_ = next;
  theta_ += omega_ * dt;
}

double Drivetrain::speed(int shaft) const {
  return drive_.shaft_ratios[static_cast<std::size_t>(shaft)] * omega_;
}
double Drivetrain::angle(int shaft) const {
  return drive_.shaft_ratios[static_cast<std::size_t>(shaft)] * theta_;
}

}  // namespace fl
