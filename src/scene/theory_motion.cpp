#include "scene/theory_motion.hpp"

namespace fl {

std::optional<HarmonicMotion> theory_motion(const CompiledRig& rig, double x, double vx) {
  if (!rig.restoring || rig.rollers.sense != RollerSense::kInward || !rig.omega)
    return std::nullopt;
  const double centre = rig.oscillation_centre.value_or(0.0);
  return HarmonicMotion{x - centre, vx, *rig.omega, centre};
}

}  // namespace fl
