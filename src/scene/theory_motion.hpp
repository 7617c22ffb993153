// The theory a front end draws beside the simulated plate (the video's x(t) strip and phase
// portrait, the page's plot of x(t)): the thick plate's harmonic motion about the rig's centre,
// started where and as the plate is. One rule for all of them, so that a tilted rig's theory
// oscillates about its x_eq wherever it is drawn.
#pragma once

#include <optional>

#include "core/harmonic_motion.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// The motion from the plate at `x` [m] with speed `vx` [m/s] at t = 0 (the run's start), or none
// when the rollers do not restore the plate (no oscillation to draw: l <= 2 mu_k h_c, or rollers
// turning outward).
std::optional<HarmonicMotion> theory_motion(const CompiledRig& rig, double x, double vx);

}  // namespace fl
