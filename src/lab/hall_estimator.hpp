// The rig's period estimator (src/estimator/period_estimator.h, the very header the Arduino
// firmware compiles) fed with the simulated Hall samples, as the lab uses it.
#pragma once

#include <memory>
#include <vector>

#include "lab/experiment.hpp"
#include "lab/host_estimator.hpp"
#include "sensor/hall_signal.hpp"

namespace fl {

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl
