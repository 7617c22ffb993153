// The plate's pose at one instant, and the pose between two physics steps: what every simulated
// instrument samples at its own clock, not the physics step's.
#pragma once

namespace fl {

// The plate's pose at one instant, enough to place what rides on it.
struct PlatePose {
  double t = 0.0;      // s
  double x = 0.0;      // m, centre of mass
  double z = 0.0;      // m, centre of mass
  double pitch = 0.0;  // rad about +y
  double vx = 0.0, vz = 0.0, pitch_rate = 0.0;
  double y = 0.0;    // m, sideways (a plate the guides let move)
  double yaw = 0.0;  // rad about +z
};

// The pose at `when` (a.t <= when <= b.t, a.t < b.t): x, z and the pitch by cubic Hermite
// interpolation between the two states (their positions and rates); the rates, the slow sideways
// motion and yaw (the guides' play) linearly.
PlatePose pose_between(const PlatePose& a, const PlatePose& b, double when);

}  // namespace fl
