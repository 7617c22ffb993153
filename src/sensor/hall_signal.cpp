#include "sensor/hall_signal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

HallSignal::HallSignal(const CompiledRig& rig)
    : magnets_(rig),
      sensor_(rig.sensor.value()),
      clock_(sensor_.sample_rate, sensor_.clock_error),
      normal_(rig.world.seed) {
  const double norm = std::hypot(sensor_.axis[0], sensor_.axis[1], sensor_.axis[2]);
  axis_ = {sensor_.axis[0] / norm, sensor_.axis[1] / norm, sensor_.axis[2] / norm};
  offset_volts_ = sensor_.offset ? *sensor_.offset : 0.5 * sensor_.supply;
}

double HallSignal::field_along_axis(const PlatePose& pose) const {
  return magnets_.field_along(pose, sensor_.position, axis_);
}

double HallSignal::voltage(double field) const {
  return offset_volts_ + sensor_.sensitivity * field;
}

std::uint16_t HallSignal::adc_code(double volts) const {
  const double full = std::ldexp(1.0, sensor_.adc_bits);
  const double code = std::floor(volts / sensor_.supply * full);
  return static_cast<std::uint16_t>(std::clamp(code, 0.0, full - 1.0));
}

void HallSignal::sample_between(const PlatePose& a, const PlatePose& b,
                                const std::function<void(const HallSample&)>& emit) {
  const double h = b.t - a.t;
  if (!(h > 0.0)) return;
  const auto take = [&](long long index) {
    const double clock = static_cast<double>(index) * clock_.interval();
    // The ADC converts at the board's clock time (true time clock / (1 + e) for a clock running
    // fast by e) plus jitter; the firmware stamps the clock's own time.
    const double when =
        true_time(index) + (sensor_.jitter > 0.0 ? sensor_.jitter * normal_.standard() : 0.0);
    const PlatePose p = pose_between(a, b, when);
    const double noise = sensor_.noise > 0.0 ? sensor_.noise * normal_.standard() : 0.0;
    HallSample sample;
    sample.t_us = static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::llround(clock * 1e6)) &
                                             0xffffffffu);
    sample.adc = adc_code(voltage(field_along_axis(p)) + noise);
    emit(sample);
  };
  clock_.due(a.t, b.t, take);
}

}  // namespace fl
