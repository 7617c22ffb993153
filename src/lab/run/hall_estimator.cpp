#include "lab/run/hall_estimator.hpp"

#include <algorithm>
#include <optional>

#include "estimator/host_estimator.hpp"

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
  std::vector<HallSample> learning_samples;  // since the estimator (re)started learning
  std::vector<double> learning_pulses;       // s
  std::size_t timed_since_restart = 0;       // index in pulse_times of the first pulse since then

  void find_learning_pulses();

  Impl(double spacing, double gravity) : estimator(rig_config(spacing, gravity)) {}
};

HallEstimator::HallEstimator(double spacing, double gravity)
    : impl_(std::make_unique<Impl>(spacing, gravity)) {}
HallEstimator::~HallEstimator() = default;
HallEstimator::HallEstimator(HallEstimator&&) noexcept = default;
HallEstimator& HallEstimator::operator=(HallEstimator&&) noexcept = default;

// At most this many samples are kept while the estimator learns (a minute at 1 kHz): a signal
// that never swings enough is never learned, and must not grow memory without end.
constexpr std::size_t kMaxLearningSamples = 60000;

void HallEstimator::Impl::find_learning_pulses() {
  const fl_estimator::PeriodEstimator& e = estimator.estimator();
  const double level = static_cast<double>(e.timing_level());
  const int polarity = e.polarity();
  const auto above = [&](const HallSample& s) { return polarity * (s.adc - level) > 0.0; };
  // The instant between two samples where the signal crosses the level (linear).
  const auto crossing = [&](const HallSample& a, const HallSample& b) {
    const double f = (level - a.adc) / (static_cast<double>(b.adc) - a.adc);
    return (a.t_us + f * (static_cast<double>(b.t_us) - a.t_us)) * 1e-6;
  };
  std::optional<double> rise;
  bool cut = false;  // the pulse began before the first sample
  for (std::size_t i = 0; i < learning_samples.size(); ++i) {
    const HallSample& s = learning_samples[i];
    if (i == 0) {
      if (above(s)) {
        rise = s.t_us * 1e-6;
        cut = true;
      }
      continue;
    }
    const HallSample& before = learning_samples[i - 1];
    if (!rise && above(s) && !above(before)) {
      rise = crossing(before, s);
      cut = false;
    } else if (rise && !above(s) && above(before)) {
      // The pulse's time as the estimator takes it: the midpoint of its rise and fall.
      learning_pulses.push_back(cut ? *rise : 0.5 * (*rise + crossing(before, s)));
      rise.reset();
    }
  }
}

void HallEstimator::add(const HallSample& sample) {
  const bool learning = impl_->estimator.estimator().phase() < fl_estimator::kIdle;
  if (learning && impl_->learning_samples.size() < kMaxLearningSamples)
    impl_->learning_samples.push_back(sample);
  const std::uint8_t events = impl_->estimator.add(sample.t_us, sample.adc);
  if (events & fl_estimator::kPulse)
    impl_->pulse_times.push_back(impl_->estimator.pulses().back().time);
  if (events & fl_estimator::kRestart) {
    // Learning again: the samples from here on.
    impl_->learning_samples.assign(1, sample);
    impl_->timed_since_restart = impl_->pulse_times.size();
  } else if (learning && impl_->estimator.estimator().phase() >= fl_estimator::kIdle) {
    // Learned and settled at the baseline: the pulses it learned from can be found now.
    impl_->find_learning_pulses();
    impl_->learning_samples.clear();
    impl_->learning_samples.shrink_to_fit();
  }
}

bool HallEstimator::signal_learned() const {
  return impl_->estimator.estimator().phase() >= fl_estimator::kIdle;
}

bool HallEstimator::geometry_known() const {
  return impl_->estimator.estimator().geometry() != fl_estimator::kAutoGeometry;
}

const std::vector<double>& HallEstimator::learning_pulse_times() const {
  return impl_->learning_pulses;
}

std::vector<double> HallEstimator::provisional_periods() const {
  if (geometry_known()) return {};
  const std::vector<double>& t = impl_->pulse_times;
  std::vector<double> intervals;
  for (std::size_t i = impl_->timed_since_restart + 1; i < t.size(); ++i)
    intervals.push_back(t[i] - t[i - 1]);
  // A pair per period: neighbouring intervals alternate, the short one under 0.6 of the long
  // one (the estimator's own test for a pair). Then a period is two intervals.
  bool pair = false;
  for (std::size_t i = 1; i < intervals.size(); ++i)
    pair = pair || std::min(intervals[i], intervals[i - 1]) <
                       0.6 * std::max(intervals[i], intervals[i - 1]);
  if (!pair) return intervals;
  std::vector<double> periods;
  for (std::size_t i = 1; i < intervals.size(); ++i)
    periods.push_back(intervals[i] + intervals[i - 1]);
  return periods;
}

EstimatorReport HallEstimator::report() const {
  // The data ends here: a turning point still open is completed, on a copy.
  return estimator_report(impl_->estimator.stats_if_finished());
}

EstimatorReport estimator_report(const fl_estimator::Stats& s) {
  EstimatorReport r;
  r.periods_used = static_cast<int>(s.periods_used);
  r.periods_discarded = static_cast<int>(s.periods_discarded);
  r.pulses = static_cast<int>(s.pulses);
  r.period = static_cast<double>(s.period_s);
  r.period_std = static_cast<double>(s.period_std_s);
  r.period_std_error = static_cast<double>(s.period_sem_s);
  r.mu_k = static_cast<double>(s.mu_k);
  r.mu_k_err_worst = static_cast<double>(s.mu_k_err_worst);
  r.mu_k_err_quadrature = static_cast<double>(s.mu_k_err_quadrature);
  return r;
}

const std::vector<double>& HallEstimator::pulse_times() const {
  return impl_->pulse_times;
}

const std::vector<EstimatedPeriod>& HallEstimator::judged_periods() const {
  return impl_->estimator.periods();
}

std::vector<EstimatedPeriod> HallEstimator::periods() const {
  return impl_->estimator.periods_if_finished();
}

}  // namespace fl
