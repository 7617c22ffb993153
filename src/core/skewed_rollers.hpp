// Rollers whose axes are not quite parallel: roller 0's axis turned by +skew/2 about the vertical,
// roller 1's by -skew/2. Both inward surfaces then move along +y at v_r sin(skew / 2) as well. The
// friction on the plate from each roller lies along its slip, so the plate's slip along y decays
// (at about mu_k g / v_r) and it drifts with the surfaces, whatever the normal forces; its slip
// is then along x alone and it oscillates as on parallel rollers (docs/physics.md). Standard
// library only.
#pragma once

namespace fl {

// The drift v_r sin(skew / 2) [m/s] for both surfaces at speed v_r [m/s] and skew [rad].
double skew_drift_speed(double surface_speed, double skew);

}  // namespace fl
