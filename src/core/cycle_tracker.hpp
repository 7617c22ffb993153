// The plate's motion cut into cycles, sample by sample: each cycle runs from an upward crossing of
// the centre to the next (times placed between samples by linear interpolation), and records its
// period, its amplitude (half its peak-to-peak), the rollers' surface speed averaged over it, and
// how long the plate moved with a roller's surface in it. Fed x, v and the rollers' surface
// velocities each step; for runs whose rollers change speed (a ramp), where one period and one
// amplitude per run say little. Standard library only.
#pragma once

#include <array>
#include <vector>

namespace fl {

struct CycleRecord {
  double start = 0.0;      // s, the upward crossing of the centre that opens the cycle
  double period = 0.0;     // s, to the next upward crossing
  double amplitude = 0.0;  // m, half of (largest x - smallest x) within the cycle
  double x_max = 0.0;      // m, the largest x within the cycle
  double x_min = 0.0;      // m, the smallest x within the cycle
  // m/s, the rollers' surface speed (the mean of the two rollers' |velocity|) averaged over the
  // cycle's time.
  double surface_speed_mean = 0.0;
  // s, the time within the cycle the plate moved with a roller's surface (0: it slipped on both
  // rollers throughout).
  double stick_duration = 0.0;
  bool stuck() const { return stick_duration > 0.0; }
};

class CycleTracker {
 public:
  // `centre` [m]: the position the cycles cross. `stick_tolerance`: the plate moves with a roller
  // when |v - u| <= stick_tolerance |u| for that roller's surface velocity u != 0.
  explicit CycleTracker(double centre = 0.0, double stick_tolerance = 5e-3)
      : centre_(centre), stick_tolerance_(stick_tolerance) {}

  // One sample: time [s] (increasing), position [m], velocity [m/s], and each roller's top's
  // velocity along +x [m/s].
  void add(double t, double x, double v, const std::array<double, 2>& surface);

  // The cycles completed so far, in time order.
  const std::vector<CycleRecord>& cycles() const { return cycles_; }

 private:
  bool stuck(double v, const std::array<double, 2>& surface) const;

  double centre_;
  double stick_tolerance_;
  bool have_previous_ = false;
  double t0_ = 0.0, x0_ = 0.0, speed0_ = 0.0;
  bool stuck0_ = false;
  // The cycle under way (since the last upward crossing).
  bool open_ = false;
  CycleRecord current_;
  double speed_integral_ = 0.0;  // m, of the surface speed over the open cycle's time
  std::vector<CycleRecord> cycles_;
};

}  // namespace fl
