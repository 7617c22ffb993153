// The rig's clock: the Arduino's micros(), a 32-bit count of microseconds that wraps around to 0
// every 2^32 us (71.6 min). MicrosClock follows its readings, taken in time order, and places
// each on one continuous axis. The Hall-log reader, the simulator's estimator and
// `frictionlab estimate` all undo the wraps through it.
#pragma once

#include <cstdint>

namespace fl {

class MicrosClock {
 public:
  static constexpr double kWrap = 4294967296.0;  // 2^32 us

  // The next reading [us] (fractions allowed) on the unwrapped axis [us]. A reading more than half
  // a wrap below the previous one, itself a reading of the 32-bit clock (below 2^32), means the
  // clock wrapped around; any other is taken as it is (a time that went back is the caller's to
  // refuse).
  double advance(double reading);

  // A 32-bit reading at or before the latest one and less than one wrap before it (an instant
  // between two samples, as the estimator reports them) on the unwrapped axis [us].
  double unwrap_past(std::uint32_t reading) const;

  // Times the clock has wrapped around so far.
  int wraps() const { return wraps_; }

 private:
  double offset_ = 0.0;  // wraps_ * kWrap [us]
  double latest_ = 0.0;  // the latest reading, as read [us]
  bool started_ = false;
  int wraps_ = 0;
};

}  // namespace fl
