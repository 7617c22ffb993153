// Period, centre and amplitude of an oscillation x(t) read from its own trajectory, sample by
// sample: the times x crosses its centre (placed between samples by cubic Hermite interpolation
// with the velocities) and the turning points. The centre crossed is the one given (a tilted
// rig's x_eq, core/tilted_rig.hpp); the trajectory's own centre is measured from its turning
// points. This is the trajectory's own measure of the
// period, independent of the Hall sensor and the estimator.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace fl {

struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
  double slope_std_error = 0.0;
  double residual_sd = 0.0;  // the residuals' standard deviation, sqrt(sum r^2 / (n - 2))
  std::size_t n = 0;
};

// Least-squares line through (x_i, y_i); slope_std_error and residual_sd from the residuals (0 for
// n <= 2).
LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

class OscillationTracker {
 public:
  explicit OscillationTracker(double centre = 0.0) : centre_(centre) {}

  // One sample of the trajectory: time [s], position [m], velocity [m/s]. Times must increase.
  void add(double t, double x, double v);

  // Crossings of the centre, alternating in direction, in time order [s].
  const std::vector<double>& crossings() const { return crossings_; }
  // |x - centre| at each turning point [m], when it happened [s], and x there [m].
  const std::vector<double>& turning_amplitudes() const { return amplitudes_; }
  const std::vector<double>& turning_times() const { return turning_times_; }
  const std::vector<double>& turning_positions() const { return turning_positions_; }

  // The oscillation's centre [m]: the mean of the midpoints of successive turning points at or
  // after `since` [s] (needs two). nullopt before that.
  std::optional<double> centre(double since = 0.0) const;

  // Period from a straight-line fit of crossing time against half-period index (needs at least
  // three crossings), with its standard error. nullopt before that. Only the crossings at or
  // after `since` [s] count (the oscillation after a stick clipped it).
  std::optional<LinearFit> period(double since = 0.0) const;

  // Relative change of the amplitude per period: slope of amplitude(t) times T over the first
  // amplitude (needs at least two turning points and a period).
  std::optional<double> amplitude_drift_per_period() const;

 private:
  double centre_;
  bool have_previous_ = false;
  double t0_ = 0.0, x0_ = 0.0, v0_ = 0.0;
  std::vector<double> crossings_;
  std::vector<double> amplitudes_;
  std::vector<double> turning_times_;
  std::vector<double> turning_positions_;
};

}  // namespace fl
