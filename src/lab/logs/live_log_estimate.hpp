// A rig's samples run through the rig's estimator as they arrive (from a serial port), kept as
// the log they make so far: what `frictionlab estimate --follow` prints and what the browser's
// live rig shows. The samples are stamped on the rig's 32-bit microsecond clock from the run's
// first sample, as `estimate` stamps a log's, so the periods judged live are those `estimate`
// finds in the recorded log.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "estimator/host_estimator.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/hall_log_reader.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

class LiveLogEstimate {
 public:
  // `keep_samples`: keep the run's samples (samples()); without, only the estimator's state.
  explicit LiveLogEstimate(const LogSetUp& set_up, bool keep_samples = true);

  // One sample of the run (in time order); returns the estimator's Event bits for it.
  std::uint8_t add(const LogSample& sample);

  const LogSetUp& set_up() const { return set_up_; }
  const HostEstimator& host() const { return *host_; }
  // The run's samples so far (kept ones), on its own time axis (t_s as read) and the rig's clock
  // (t_us).
  const HallLog& samples() const { return samples_; }
  // The last sample's time on the rig's clock [us].
  std::uint32_t last_t_us() const { return last_t_us_; }
  // The time of the run's first sample on the log's axis [s] (none before one came).
  std::optional<double> origin() const { return t0_; }

 private:
  LogSetUp set_up_;
  std::unique_ptr<HostEstimator> host_;
  bool keep_samples_ = true;
  std::optional<double> t0_;
  std::uint32_t last_t_us_ = 0;
  HallLog samples_;
};

}  // namespace fl
