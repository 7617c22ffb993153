#include "lab/logs/live_log_estimate.hpp"

#include <cmath>

namespace fl {

LiveLogEstimate::LiveLogEstimate(const LogSetUp& set_up, bool keep_samples)
    : set_up_(set_up),
      host_(std::make_unique<HostEstimator>(set_up.config())),
      keep_samples_(keep_samples) {}

std::uint8_t LiveLogEstimate::add(const LogSample& s) {
  if (!t0_) t0_ = s.t_s;
  const auto us = static_cast<std::uint64_t>(std::llround((s.t_s - *t0_) * 1e6));
  last_t_us_ = static_cast<std::uint32_t>(us & 0xFFFFFFFFu);
  if (keep_samples_) {
    samples_.t_s.push_back(s.t_s);
    samples_.adc.push_back(s.adc);
    samples_.line.push_back(s.line);
    samples_.t_us.push_back(last_t_us_);
  }
  return host_->add(last_t_us_, s.adc);
}

}  // namespace fl
