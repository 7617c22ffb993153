#include "core/skewed_rollers.hpp"

#include <cmath>

namespace fl {

double skew_drift_speed(double surface_speed, double skew) {
  return surface_speed * std::sin(0.5 * skew);
}

}  // namespace fl
