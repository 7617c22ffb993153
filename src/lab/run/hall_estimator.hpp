// The rig's period estimator (src/estimator/period_estimator.h, the very header the Arduino
// firmware compiles) fed with the simulated Hall samples, as the lab uses it.
#pragma once

#include <memory>
#include <vector>

#include "estimator/host_estimator.hpp"
#include "lab/run/experiment.hpp"
#include "sensor/hall_signal.hpp"

namespace fl {

// The estimator's statistics as the lab reports them (the summary's, a live frame's).
EstimatorReport estimator_report(const fl_estimator::Stats& stats);

class HallEstimator {
 public:
  // l [m] and g [m/s^2] for mu_k; the paper's dl = 2 mm for its uncertainty.
  HallEstimator(double spacing, double gravity);
  ~HallEstimator();
  HallEstimator(HallEstimator&&) noexcept;
  HallEstimator& operator=(HallEstimator&&) noexcept;

  void add(const HallSample& sample);
  EstimatorReport report() const;
  // Times [s] of the pulses detected so far (for overlays and plots).
  const std::vector<double>& pulse_times() const;
  // Every period judged so far, accepted or rejected, on the rig's clock [s], as report() counts
  // them (the data ending here).
  std::vector<EstimatedPeriod> periods() const;
  // The periods judged so far, without the one the data's end would complete (for live overlays).
  const std::vector<EstimatedPeriod>& judged_periods() const;

  // For live overlays, before the estimator's first period.
  // Whether the estimator knows the signal (baseline, polarity, pulse height) and times pulses.
  bool signal_learned() const;
  // Whether it has recognised one pulse or a pair per period (its periods start then).
  bool geometry_known() const;
  // The pulses it learned the signal from, which it does not time: found afterwards in the
  // samples it learned from, with the levels it learned [s]. A pulse cut by the start of the data
  // (the magnet released at the sensor) is placed at the first sample.
  const std::vector<double>& learning_pulse_times() const;
  // Until the geometry is known: the periods the pulses timed so far give if each period shows
  // one pulse (the intervals between them), or a pair when the intervals alternate short and long
  // as a pair's do (the sums of two). Empty once the estimator's own periods start.
  std::vector<double> provisional_periods() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl
