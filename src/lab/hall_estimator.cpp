#include "lab/hall_estimator.hpp"

#include "estimator/period_estimator.h"

namespace fl {

struct HallEstimator::Impl {
  fl_estimator::BasicPeriodEstimator<> estimator;
  std::vector<double> pulse_times;
  std::uint64_t wraps = 0;  // the 32-bit microsecond clock wraps every 71.6 min
  std::uint32_t last_us = 0;

  Impl(double spacing, double gravity)
      : estimator(static_cast<float>(spacing), 0.002f, static_cast<float>(gravity)) {}

  double seconds(const fl_estimator::Instant& t) const {
    // A pulse lies before the latest sample: if its clock is ahead of it, it precedes a wrap.
    const std::uint64_t epoch = t.us > last_us && wraps > 0 ? wraps - 1 : wraps;
    return (static_cast<double>(epoch) * 4294967296.0 + static_cast<double>(t.us) +
            static_cast<double>(t.frac) / 256.0) *
           1e-6;
  }
};

HallEstimator::HallEstimator(double spacing, double gravity)
    : impl_(std::make_unique<Impl>(spacing, gravity)) {}
HallEstimator::~HallEstimator() = default;
HallEstimator::HallEstimator(HallEstimator&&) noexcept = default;
HallEstimator& HallEstimator::operator=(HallEstimator&&) noexcept = default;

void HallEstimator::add(const HallSample& sample) {
  if (sample.t_us < impl_->last_us) ++impl_->wraps;
  impl_->last_us = sample.t_us;
  const std::uint8_t events = impl_->estimator.add_sample(sample.t_us, sample.adc);
  if (events & fl_estimator::kPulse) {
    const std::uint32_t last = impl_->estimator.pulse_count() - 1;
    impl_->pulse_times.push_back(impl_->seconds(impl_->estimator.pulse(last).time));
  }
}

EstimatorReport HallEstimator::report() const {
  // The data ends here: a turning point still open is completed, on a copy.
  fl_estimator::BasicPeriodEstimator<> finished = impl_->estimator;
  finished.finish();
  const fl_estimator::Stats s = finished.stats();
  EstimatorReport r;
  r.periods_used = static_cast<int>(s.periods_used);
  r.periods_discarded = static_cast<int>(s.periods_discarded);
  r.pulses = static_cast<int>(s.pulses);
  r.period = s.period_s;
  r.period_std = s.period_std_s;
  r.period_std_error = s.period_sem_s;
  r.mu_k = s.mu_k;
  r.mu_k_err_worst = s.mu_k_err_worst;
  r.mu_k_err_quadrature = s.mu_k_err_quadrature;
  return r;
}

const std::vector<double>& HallEstimator::pulse_times() const {
  return impl_->pulse_times;
}

}  // namespace fl
