#include "core/cycle_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace fl {

bool CycleTracker::stuck(double v, const std::array<double, 2>& surface) const {
  for (const double u : surface)
    if (u != 0.0 && std::fabs(v - u) <= stick_tolerance_ * std::fabs(u)) return true;
  return false;
}

void CycleTracker::add(double t, double x, double v, const std::array<double, 2>& surface) {
  const double speed = 0.5 * (std::fabs(surface[0]) + std::fabs(surface[1]));
  const bool is_stuck = stuck(v, surface);
  if (!have_previous_) {
    have_previous_ = true;
    t0_ = t;
    x0_ = x;
    speed0_ = speed;
    stuck0_ = is_stuck;
    return;
  }
  const double dt = t - t0_;
  // Adds the part [t0_ + a dt, t0_ + b dt] of this interval to the open cycle: the surface speed
  // (trapezoidal) and the stick time (each end of the interval counts for half).
  const auto accumulate = [&](double a, double b) {
    if (!open_) return;
    const double sa = speed0_ + a * (speed - speed0_);
    const double sb = speed0_ + b * (speed - speed0_);
    speed_integral_ += 0.5 * (sa + sb) * (b - a) * dt;
    current_.stick_duration +=
        0.5 * ((stuck0_ ? 1.0 : 0.0) + (is_stuck ? 1.0 : 0.0)) * (b - a) * dt;
  };
  const bool upward = x0_ - centre_ < 0.0 && x - centre_ >= 0.0;
  if (upward) {
    const double f = (centre_ - x0_) / (x - x0_);  // in (0, 1]
    const double crossing = t0_ + f * dt;
    accumulate(0.0, f);
    if (open_) {
      current_.period = crossing - current_.start;
      current_.amplitude = 0.5 * (current_.x_max - current_.x_min);
      current_.surface_speed_mean = speed_integral_ / current_.period;
      cycles_.push_back(current_);
    }
    open_ = true;
    current_ = CycleRecord{};
    current_.start = crossing;
    current_.x_max = x;
    current_.x_min = x;
    speed_integral_ = 0.0;
    accumulate(f, 1.0);
  } else {
    accumulate(0.0, 1.0);
    if (open_) {
      current_.x_max = std::max(current_.x_max, x);
      current_.x_min = std::min(current_.x_min, x);
    }
  }
  t0_ = t;
  x0_ = x;
  speed0_ = speed;
  stuck0_ = is_stuck;
}

}  // namespace fl
