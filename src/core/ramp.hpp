// A quantity scheduled over time: piecewise linear between given points (time, value), held at
// the first point's value before it and at the last point's value after it. The rollers' speed
// or the motor's duty of a run that ramps (scene keys rollers.speed_ramp, drive.motor.duty_ramp).
// Standard library only.
#pragma once

#include <cstddef>
#include <vector>

namespace fl {

struct RampPoint {
  double at = 0.0;     // s since the run's start
  double value = 0.0;  // in the scheduled quantity's unit (rad/s for a speed, 0..1 for a duty)
};

class Ramp {
 public:
  // Refuses (fl::DomainError) an empty list, a time or value that is not finite, a time < 0, and
  // times that do not strictly increase.
  explicit Ramp(std::vector<RampPoint> points);

  // The value at time t [s].
  double at(double t) const;
  // The slope d value / dt at time t [unit/s]: that of the segment t lies in (0 outside them; at
  // a point, the segment after it).
  double slope(double t) const;

  // The smallest and largest value taken over [t0, t1] (t0 <= t1): the ends and every point
  // between them.
  double smallest(double t0, double t1) const;
  double largest(double t0, double t1) const;
  // Over all time.
  double smallest() const;
  double largest() const;

  const std::vector<RampPoint>& points() const { return points_; }

 private:
  std::vector<RampPoint> points_;
};

}  // namespace fl
