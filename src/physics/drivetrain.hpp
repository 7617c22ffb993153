// The rig's drive (internal to src/physics): the motor, the gearbox's stages and the idlers that
// couple the rollers, as one rigid gear train. Every shaft of the drive layout turns at a fixed
// multiple of the motor's speed, taken from the meshing gears' tooth counts (each mesh:
// omega_driven = -omega_driver x teeth_driver / teeth_driven), so the train has one degree of
// freedom: the motor's angle. Its equation of motion is
//     J omega' = s (duty tau_stall - c s omega) + sum_i u_i tau_i,   c = tau_stall / omega_0,
// with J the whole train's inertia seen at the motor (sum I_k u_k^2), u_i the rollers' speed
// ratios, tau_i the torques the plate's friction puts on the rollers, and s the motor's sense.
// It is integrated each step, linearly implicit in the back-EMF damping (stable at any step),
// and drives the kinematic rollers of the Bullet world. docs/physics.md says why the train is
// not a chain of Bullet gear constraints.
#pragma once

#include <array>
#include <vector>

#include "scene/compiled_rig.hpp"

namespace fl {

class Drivetrain {
 public:
  // The train of the compiled rig's drive (its layout, ratios and inertia), started at its
  // no-load speed for the duty at t = 0; the rig must outlive the train.
  explicit Drivetrain(const CompiledRig& rig);

  // Advances the train by dt under the torques [N m, about +y] the plate's friction put on the
  // two rollers during the last step, the motor at PWM duty `duty` (0 to 1) over the step.
  // `holding_torque` [N m, >= 0] is the most the plate's static friction can hold the rollers with
  // (mu_s N_i a at each, seen at the motor). A train that the friction brings to rest stops there
  // (its speed does not cross zero within a step: friction cannot reverse it), and stays at rest
  // while the motor's torque at rest is at most the holding torque: the plate's friction holds the
  // stalled train, as it holds a stuck contact. Without this the explicit coupling (the load is
  // the last step's) makes a stalled train chatter between rest and a step's worth of motor
  // acceleration (docs/physics.md).
  void advance(double dt, const std::array<double, 2>& roller_torques, double duty,
               double holding_torque);

  double motor_speed() const { return omega_; }          // rad/s about +y
  double motor_torque() const { return motor_torque_; }  // N m, in the driving sense
  double speed(int shaft) const;                         // rad/s about +y
  double angle(int shaft) const;                         // rad about +y since the start
  std::array<double, 2> roller_speeds() const { return {speed(0), speed(1)}; }
  const DriveLayout& layout() const { return drive_.layout; }

 private:
  const CompiledDrive& drive_;
  const MotorDesc& motor_;
  double omega_ = 0.0;  // rad/s, the motor's
  double theta_ = 0.0;  // rad, the motor's
  double motor_torque_ = 0.0;
};

}  // namespace fl
