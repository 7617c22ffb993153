// A sensor's own clock, sampling the run between its physics steps: sample k is stamped
// k / rate on the clock, and taken at the true time k / (rate (1 + clock_error)) of a clock that
// runs fast by clock_error (an Arduino's resonator; a phone's clock is the run's). Each step asks
// which samples fall in it.
#pragma once

namespace fl {

class SampleClock {
 public:
  explicit SampleClock(double rate, double clock_error = 0.0)
      : interval_(1.0 / rate), clock_error_(clock_error) {}

  double interval() const { return interval_; }
  // The true time [s] at which the clock reads sample `index`'s time.
  double true_time(long long index) const {
    return static_cast<double>(index) * interval_ / (1.0 + clock_error_);
  }

  // Calls take(index), in order, for every sample whose true time falls in (a, b] [s], and for
  // sample 0 on the first call when a <= 0.
  template <typename Take>
  void due(double a, double b, Take take) {
    if (first_) {
      first_ = false;
      if (a <= 0.0) take(0LL);
    }
    while (true_time(next_index_) <= b + 1e-12 * interval_) {
      take(next_index_);
      ++next_index_;
    }
  }

 private:
  double interval_;
  double clock_error_;
  long long next_index_ = 1;  // sample 0 is at t = 0, taken by the first call
  bool first_ = true;
};

}  // namespace fl
