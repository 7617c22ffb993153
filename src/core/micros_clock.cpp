#include "core/micros_clock.hpp"

namespace fl {

double MicrosClock::advance(double reading) {
  if (started_ && latest_ - reading > kWrap / 2.0 && latest_ < kWrap) {
    offset_ += kWrap;
    ++wraps_;
  }
  started_ = true;
  latest_ = reading;
  return offset_ + reading;
}

double MicrosClock::unwrap_past(std::uint32_t reading) const {
  const double r = static_cast<double>(reading);
  // A reading ahead of the latest one was taken before the last wrap.
  return (r > latest_ && wraps_ > 0 ? offset_ - kWrap : offset_) + r;
}

}  // namespace fl
