#include "lab/hall_estimator.hpp"

#include "lab/host_estimator.hpp"

namespace fl {
namespace {

// The paper's uncertainty of the roller spacing, dl = 2 mm.
constexpr float kSpacingErr = 0.002f;

fl_estimator::Config rig_config(double spacing, double gravity) {
  fl_estimator::Config config;
  config.spacing_m = static_cast<float>(spacing);
  config.spacing_err_m = kSpacingErr;
  config.gravity_m_s2 = static_cast<float>(gravity);
  return config;
}

}  // namespace

struct HallEstimator::Impl {
  HostEstimator estimator;
  std::vector<double> pulse_times;

  Impl(double spacing, double gravity) : estimator(rig_config(spacing, gravity)) {}
};

HallEstimator::HallEstimator(double spacing, double gravity)
    : impl_(std::make_unique<Impl>(spacing, gravity)) {}
HallEstimator::~HallEstimator() = default;
HallEstimator::HallEstimator(HallEstimator&&) noexcept = default;
HallEstimator& HallEstimator::operator=(HallEstimator&&) noexcept = default;

void HallEstimator::add(const HallSample& sample) {
  if (impl_->estimator.add(sample.t_us, sample.adc) & fl_estimator::kPulse)
    impl_->pulse_times.push_back(impl_->estimator.pulses().back().time);
}

EstimatorReport HallEstimator::report() const {
  // The data ends here: a turning point still open is completed, on a copy.
  const fl_estimator::Stats s = impl_->estimator.stats_if_finished();
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

std::vector<EstimatedPeriod> HallEstimator::periods() const {
  return impl_->estimator.periods_if_finished();
}

}  // namespace fl
