// The time integrator's own error on the oscillation (docs/physics.md): Bullet's semi-implicit
// Euler step shortens a harmonic period by (omega dt)^2 / 24 to leading order, so a period
// tolerance sets the largest step.
#pragma once

namespace fl {

// Relative period error -(omega dt)^2 / 24 for angular frequency omega [rad/s] and step dt [s].
double integrator_period_bias(double omega, double time_step);

// The largest step [s] whose predicted |bias| is `bias` (relative, > 0): sqrt(24 bias) / omega.
double step_for_period_bias(double omega, double bias);

}  // namespace fl
