#include "core/harmonic_motion.hpp"

#include <cmath>

namespace fl {

double HarmonicMotion::at(double t) const {
  return centre + x0 * std::cos(omega * t) +
         (omega > 0.0 ? v0 / omega * std::sin(omega * t) : v0 * t);
}

double HarmonicMotion::velocity_at(double t) const {
  return omega > 0.0 ? -x0 * omega * std::sin(omega * t) + v0 * std::cos(omega * t) : v0;
}

}  // namespace fl
