// x(t) of the harmonic oscillation the thick-plate formula describes (the theory every front end
// draws beside the simulated plate: the video's strip and phase portrait, the page's plot):
// started at x0 from its centre with speed v0 at t = 0, angular frequency omega, about `centre`
// (a tilted rig's x_eq, 0 on a level one).
#pragma once

namespace fl {

struct HarmonicMotion {
  double x0 = 0.0;      // m, from the centre
  double v0 = 0.0;      // m/s
  double omega = 0.0;   // rad/s
  double centre = 0.0;  // m

  double at(double t) const;           // m
  double velocity_at(double t) const;  // m/s, dx/dt
};

}  // namespace fl
