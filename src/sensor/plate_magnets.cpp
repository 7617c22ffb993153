#include "sensor/plate_magnets.hpp"

#include <cmath>

#include "sensor/dipole_field.hpp"

namespace fl {

PlateMagnets::PlateMagnets(const CompiledRig& rig) {
  const PlateMass& pm = rig.plate;
  for (const MagnetDesc& m : rig.magnets) {
    magnets_.push_back(
        {{m.x - pm.x_c, 0.0, rig.plate_desc.thickness + m.height + 0.5 * m.thickness - pm.h_c},
         magnet_moment(m)});
  }
}

template <class Add>
void PlateMagnets::each_field(const PlatePose& pose, const Vec3& point, Add add) const {
  const double c = std::cos(pose.pitch), s = std::sin(pose.pitch);
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  for (const MagnetOnPlate& m : magnets_) {
    // The plate's frame turned by the pitch about +y (x' = x c + z s, z' = -x s + z c), then by
    // the yaw about +z, and carried to the plate's centre of mass (x, y, z).
    const double px = m.offset[0] * c + m.offset[2] * s;
    const double py = m.offset[1];
    const Vec3 at{pose.x + (px * cy - py * sy), pose.y + (px * sy + py * cy),
                  pose.z - m.offset[0] * s + m.offset[2] * c};
    const Vec3 moment{m.moment * s * cy, m.moment * s * sy, m.moment * c};
    add(dipole_field(moment, at, point));
  }
}

Vec3 PlateMagnets::field(const PlatePose& pose, const Vec3& point) const {
  Vec3 b{0.0, 0.0, 0.0};
  each_field(pose, point, [&b](const Vec3& one) {
    for (std::size_t k = 0; k < 3; ++k) b[k] += one[k];
  });
  return b;
}

double PlateMagnets::field_along(const PlatePose& pose, const Vec3& point, const Vec3& axis) const {
  double b = 0.0;
  each_field(pose, point,
             [&](const Vec3& one) { b += one[0] * axis[0] + one[1] * axis[1] + one[2] * axis[2]; });
  return b;
}

}  // namespace fl
