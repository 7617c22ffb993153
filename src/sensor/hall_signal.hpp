// The simulated Hall sensor: the magnets on the plate are point dipoles carried by the plate;
// the sensor measures the field along its axis, adds its offset, noise and clipping, and an ADC
// samples it at its own clock (not the physics step: the plate's state is interpolated between
// steps), with jitter. Each sample is (t_us, adc) as the rig's Arduino records it.
#pragma once

#include <cstdint>
#include <functional>

#include "core/normal_draws.hpp"
#include "scene/compiled_rig.hpp"
#include "sensor/plate_magnets.hpp"
#include "sensor/plate_pose.hpp"
#include "sensor/sample_clock.hpp"

namespace fl {

struct HallSample {
  std::uint32_t t_us = 0;  // the ADC clock's time stamp, microseconds
  std::uint16_t adc = 0;   // 0 .. 2^bits - 1
};

class HallSignal {
 public:
  // Needs the scene's sensor. The noise and the jitter come from its world.seed.
  explicit HallSignal(const CompiledRig& rig);

  // Field component along the sensor's axis [T] for the plate at `pose`.
  double field_along_axis(const PlatePose& pose) const;
  // Sensor output [V] for a field [T], before noise and clipping.
  double voltage(double field) const;
  // ADC code for a voltage (clipped to the rails).
  std::uint16_t adc_code(double volts) const;

  // Emits, in time order, every sample whose clock time falls in (a.t, b.t], evaluating the
  // plate's pose by cubic Hermite interpolation between the two physics states.
  void sample_between(const PlatePose& a, const PlatePose& b,
                      const std::function<void(const HallSample&)>& emit);

  // The true time [s] at which the board's clock reads sample `index`'s time.
  double true_time(long long index) const { return clock_.true_time(index); }

 private:
  PlateMagnets magnets_;
  SensorDesc sensor_;
  Vec3 axis_{};
  double offset_volts_ = 0.0;
  SampleClock clock_;
  // The noise and the jitter: the same bits on every standard library (core/normal_draws.hpp).
  NormalDraws normal_;
};

}  // namespace fl
