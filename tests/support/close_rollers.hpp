// Rigs on rollers 10 mm apart, where the contact solver's split is ill-conditioned (e =
// (l/2)^2 / k^2 = 0.0075): tests of the solver's convergence and of runs that start again at more
// iterations use them.
#pragma once

#include <numbers>

#include "scene/scene.hpp"

namespace fl::test {

// The minimal plate on rollers 10 mm apart, released 2 mm off centre (T_thick = 0.243 s).
inline Scene close_rollers() {
  Scene s;
  s.friction.mu_k = 0.29;
  s.rollers.spacing = 0.010;
  s.rollers.radius = 0.004;
  s.plate.offset = 0.002;
  s.world.duration = 3.0;
  return s;
}

// The same rollers at 60 rpm: their surface (25 mm/s) is slower than the plate gets (omega A =
// 52 mm/s), so at t = 0.020 s the plate catches roller 1's surface and moves with it for 70 ms.
// A stuck contact's friction is static, not known before the solve: the solver starts it from
// Bullet's own warm start and iterates to the balance, on a split as ill-conditioned as before,
// and a run raises its iterations.
inline Scene stuck_on_close_rollers() {
  Scene s = close_rollers();
  s.rollers.speed = 60.0 * 2.0 * std::numbers::pi / 60.0;
  return s;
}

}  // namespace fl::test
