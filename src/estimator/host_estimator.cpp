#include "estimator/host_estimator.hpp"

namespace fl {

HostEstimator::HostEstimator(const fl_estimator::Config& config, double origin)
    : estimator_(config), origin_(origin) {}

std::uint8_t HostEstimator::add(std::uint32_t t_us, std::uint16_t adc) {
  clock_.advance(static_cast<double>(t_us));
  const std::uint8_t events = estimator_.add_sample(t_us, adc);
  if (events != fl_estimator::kNoEvent) collect();
  return events;
}

void HostEstimator::finish() {
  estimator_.finish();
  collect();
}

fl_estimator::Stats HostEstimator::stats_if_finished() const {
  fl_estimator::PeriodEstimator finished = estimator_;
  finished.finish();
  return finished.stats();
}

std::vector<EstimatedPeriod> HostEstimator::periods_if_finished() const {
  HostEstimator finished = *this;
  finished.finish();
  return finished.periods_;
}

// The estimator keeps only its latest pulses and periods: each sample's are taken as they come.
void HostEstimator::collect() {
  for (; pulses_seen_ < estimator_.pulse_count(); ++pulses_seen_) {
    if (!estimator_.has_pulse(pulses_seen_)) continue;
    const fl_estimator::Pulse& p = estimator_.pulse(pulses_seen_);
    pulses_.push_back({seconds(p.time), seconds(p.rise), seconds(p.fall), p.peak, p.distorted});
  }
  for (; periods_seen_ < estimator_.period_count(); ++periods_seen_) {
    if (!estimator_.has_period(periods_seen_)) continue;
    const fl_estimator::Period& p = estimator_.period(periods_seen_);
    periods_.push_back(
        {seconds(p.start), seconds(p.end), static_cast<double>(p.period_us) * 1e-6, p.status});
  }
}

// An instant the estimator reports lies at or before the latest sample.
double HostEstimator::seconds(const fl_estimator::Instant& t) const {
  return origin_ + (clock_.unwrap_past(t.us) + static_cast<double>(t.frac) / 256.0) * 1e-6;
}

}  // namespace fl
