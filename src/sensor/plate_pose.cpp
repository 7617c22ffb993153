#include "sensor/plate_pose.hpp"

namespace fl {
namespace {

// The cubic through (0, p0) and (1, p1) with slopes h v0 and h v1, at s.
double hermite(double s, double h, double p0, double p1, double v0, double v1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * v1;
}

}  // namespace

PlatePose pose_between(const PlatePose& a, const PlatePose& b, double when) {
  const double h = b.t - a.t;
  const double s = (when - a.t) / h;
  PlatePose p;
  p.t = when;
  p.x = hermite(s, h, a.x, b.x, a.vx, b.vx);
  p.z = hermite(s, h, a.z, b.z, a.vz, b.vz);
  p.pitch = hermite(s, h, a.pitch, b.pitch, a.pitch_rate, b.pitch_rate);
  // The rates, linearly (a phone on the plate needs the pitch's; the Hall sensor none).
  p.vx = a.vx + s * (b.vx - a.vx);
  p.vz = a.vz + s * (b.vz - a.vz);
  p.pitch_rate = a.pitch_rate + s * (b.pitch_rate - a.pitch_rate);
  p.y = a.y + s * (b.y - a.y);
  p.yaw = a.yaw + s * (b.yaw - a.yaw);
  return p;
}

}  // namespace fl
