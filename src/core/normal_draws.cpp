#include "core/normal_draws.hpp"
#include "core/units.hpp"

#include <cmath>
#include <numbers>

namespace fl {

double NormalDraws::uniform_open_zero() {
  // (k + 1) / 2^53 for k in [0, 2^53): never 0, so the logarithm below is finite.
  return static_cast<double>((engine_() >> 11) + 1) * 0x1.0p-53;
}

double NormalDraws::standard() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // Box-Muller: two uniforms give two independent standard normals; keep the second.
  const double radius = std::sqrt(-2.0 * std::log(uniform_open_zero()));
  const double angle = 2.0 * kPi * uniform_open_zero();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

}  // namespace fl
