// The time integrator's own error on the oscillation (docs/physics.md): Bullet's semi-implicit
// Euler step shortens a harmonic period by (omega dt)^2 / 24 to leading order, so a period
// tolerance sets the largest step.
#pragma once

namespace fl {

// Relative period error -(omega dt)^2 / 24 for angular frequency omega [rad/s] and step dt [s].
double integrator_period_bias(double omega, double time_step);

// The largest step [s] whose predicted |bias| is `bias` (relative, > 0): sqrt(24 bias) / omega.
double step_for_period_bias(double omega, double bias);

// The loosest period accuracy a step sized by the bias can honour (relative: 10 %). The bias is
// the leading order of the error; at an accuracy a the step (90 % of a to the bias,
// lab/run/step_choice.hpp) is omega dt = sqrt(21.6 a): 1.47 rad at 10 %, and at 11.4 % it reaches
// a quarter of the period (pi/2 rad), a step that resolves no oscillation and that no scene may
// take (scene/scene_checks.cpp). A looser target is no accuracy the rule can give.
inline constexpr double kLoosestPeriodAccuracy = 0.1;

}  // namespace fl
