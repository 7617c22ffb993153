// A rig that is not level: the line through the rollers' tops rises by `tilt` toward +x. In the
// rig's own frame gravity has a component g cos(tilt) against the rollers' plane and
// -g sin(tilt) along it. The first sets the normal forces and with them the friction's restoring
// force, as g does on a level rig; the second acts at the centre of mass (no torque about it, so
// the normal forces still share the weight as on a level rig, with g cos(tilt)) and only shifts
// where the net friction balances it. For coulomb friction with both rollers slipping (rollers
// turning inward, docs/physics.md):
//
//   Omega^2 = 2 mu_k g cos(tilt) / (l - 2 mu_k h_c)
//   x_eq    = -g sin(tilt) / Omega^2 = -(l - 2 mu_k h_c) tan(tilt) / (2 mu_k)
//
// and a roller unloads where it does on a level rig, at |x| = l/2 - mu_k h_c, so the largest
// amplitude about x_eq before one does is l/2 - mu_k h_c - |x_eq|. Standard library only.
#pragma once

namespace fl {

// g cos(tilt): what presses the plate on its rollers [m/s^2].
double gravity_normal(double gravity, double tilt);

// The centre x_eq of the oscillation [m]; refuses l <= 2 mu_k h_c (no restoring force) and
// |tilt| >= pi / 2 with fl::DomainError.
double oscillation_centre(double spacing, double mu_k, double h_c, double tilt);

// The same where the two rollers' coefficients differ: mu_0 at roller 0 (x = -l/2), mu_1 at roller
// 1 (rollers at different speeds under a slip-speed law: each its mu at its own surface speed). At
// rest the net friction balances the slope's pull, S = m g sin(tilt), so its torque about the
// centre of mass is h_c S and
//   x_eq = h_c tan(tilt) - (l/2) ((mu_1 - mu_0) + 2 tan(tilt)) / (mu_0 + mu_1),
// on a level rig (l/2) (mu_0 - mu_1) / (mu_0 + mu_1) whatever h_c (docs/physics.md). Refuses
// mu_0 + mu_1 <= 0, l <= (mu_0 + mu_1) h_c and |tilt| >= pi / 2 with fl::DomainError.
double oscillation_centre(double spacing, double mu_0, double mu_1, double h_c, double tilt);

}  // namespace fl
