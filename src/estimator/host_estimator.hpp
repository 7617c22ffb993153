// The rig's period estimator (src/estimator/period_estimator.h, the very header the Arduino
// firmware compiles) run on the host: fed samples stamped by the rig's 32-bit microsecond clock,
// it keeps every pulse and period the estimator reports, in seconds on one continuous time axis
// (the clock's wraps undone by MicrosClock). The simulator's HallEstimator and
// `frictionlab estimate` (log_estimate) both run the estimator through it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/micros_clock.hpp"
#include "estimator/period_estimator.h"

namespace fl {

// A pulse as the estimator timed it [s]: its time (the turning point, for one pulse per period),
// the rise and fall crossings of the timing level; its peak [counts] and whether it was distorted.
struct EstimatedPulse {
  double time = 0.0;
  double rise = 0.0;
  double fall = 0.0;
  int peak = 0;
  bool distorted = false;
};

// A period the estimator judged: between two turning points [s], its length [s] and its
// fl_estimator::PeriodStatus (accepted, or rejected as an outlier or at a broken turning point).
struct EstimatedPeriod {
  double start = 0.0;
  double end = 0.0;
  double period = 0.0;
  std::uint8_t status = fl_estimator::kAccepted;
};

class HostEstimator {
 public:
  // `origin` [s]: the time of clock reading 0 on the caller's axis.
  explicit HostEstimator(const fl_estimator::Config& config, double origin = 0.0);

  // One sample: t_us on the rig's clock (in time order; it may wrap), adc [counts]. Returns the
  // estimator's Event bits for it.
  std::uint8_t add(std::uint32_t t_us, std::uint16_t adc);
  // The data ends here: a turning point still open is completed (and its period kept).
  void finish();
  // The statistics as they would be if the data ended now; the estimator itself goes on.
  fl_estimator::Stats stats_if_finished() const;
  // The periods likewise: those judged so far and the one a finish would complete.
  std::vector<EstimatedPeriod> periods_if_finished() const;

  const fl_estimator::PeriodEstimator& estimator() const { return estimator_; }
  const std::vector<EstimatedPulse>& pulses() const { return pulses_; }
  const std::vector<EstimatedPeriod>& periods() const { return periods_; }

 private:
  void collect();
  double seconds(const fl_estimator::Instant& t) const;

  fl_estimator::PeriodEstimator estimator_;
  MicrosClock clock_;
  double origin_ = 0.0;
  std::vector<EstimatedPulse> pulses_;
  std::vector<EstimatedPeriod> periods_;
  std::uint32_t pulses_seen_ = 0;   // the estimator's pulses collected so far
  std::uint32_t periods_seen_ = 0;  // and periods
};

}  // namespace fl
