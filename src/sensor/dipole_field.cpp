#include "sensor/dipole_field.hpp"
#include "core/units.hpp"

#include <cmath>
#include <numbers>

namespace fl {

double magnet_moment(const MagnetDesc& magnet) {
  const double r = 0.5 * magnet.diameter;
  return magnet.remanence * kPi * r * r * magnet.thickness / kMu0;
}

Vec3 dipole_field(const Vec3& moment, const Vec3& at, const Vec3& point) {
  const Vec3 r{point[0] - at[0], point[1] - at[1], point[2] - at[2]};
  const double d2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const double d = std::sqrt(d2);
  const double m_dot_r = moment[0] * r[0] + moment[1] * r[1] + moment[2] * r[2];
  // mu_0 / (4 pi) = 1e-7 exactly enough (kMu0 / (4 pi)).
  const double k = kMu0 / (4.0 * kPi) / (d2 * d2 * d);
  return {k * (3.0 * m_dot_r * r[0] - d2 * moment[0]), k * (3.0 * m_dot_r * r[1] - d2 * moment[1]),
          k * (3.0 * m_dot_r * r[2] - d2 * moment[2])};
}

}  // namespace fl
