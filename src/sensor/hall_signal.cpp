#include "sensor/hall_signal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sensor/dipole_field.hpp"

namespace fl {
namespace {

double hermite(double s, double h, double p0, double p1, double v0, double v1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * v1;
}

}  // namespace

HallSignal::HallSignal(const CompiledRig& rig) : sensor_(rig.sensor.value()), rng_(rig.world.seed) {
  const PlateMass& pm = rig.plate;
  for (const MagnetDesc& m : rig.magnets) {
    magnets_.push_back(
        {{m.x - pm.x_c, 0.0, rig.plate_desc.thickness + m.height + 0.5 * m.thickness - pm.h_c},
         magnet_moment(m)});
  }
  const double norm = std::hypot(sensor_.axis[0], sensor_.axis[1], sensor_.axis[2]);
  axis_ = {sensor_.axis[0] / norm, sensor_.axis[1] / norm, sensor_.axis[2] / norm};
  offset_volts_ = sensor_.offset ? *sensor_.offset : 0.5 * sensor_.supply;
  interval_ = 1.0 / sensor_.sample_rate;
}

double HallSignal::field_along_axis(const PlatePose& pose) const {
  const double c = std::cos(pose.pitch), s = std::sin(pose.pitch);
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  double b = 0.0;
  for (const MagnetOnPlate& m : magnets_) {
    // The plate's frame turned by the pitch about +y (x' = x c + z s, z' = -x s + z c), then by
    // the yaw about +z, and carried to the plate's centre of mass (x, y, z).
    const double px = m.offset[0] * c + m.offset[2] * s;
    const double py = m.offset[1];
    const Vec3 at{pose.x + (px * cy - py * sy), pose.y + (px * sy + py * cy),
                  pose.z - m.offset[0] * s + m.offset[2] * c};
    const Vec3 moment{m.moment * s * cy, m.moment * s * sy, m.moment * c};
    const Vec3 field = dipole_field(moment, at, sensor_.position);
    b += field[0] * axis_[0] + field[1] * axis_[1] + field[2] * axis_[2];
  }
  return b;
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
    const double clock = static_cast<double>(index) * interval_;
    // The ADC converts at the board's clock time (true time clock / (1 + e) for a clock running
    // fast by e) plus jitter; the firmware stamps the clock's own time.
    const double when =
        true_time(index) + (sensor_.jitter > 0.0 ? sensor_.jitter * unit_normal_(rng_) : 0.0);
    const double s = (when - a.t) / h;
    PlatePose p;
    p.t = when;
    p.x = hermite(s, h, a.x, b.x, a.vx, b.vx);
    p.z = hermite(s, h, a.z, b.z, a.vz, b.vz);
    p.pitch = hermite(s, h, a.pitch, b.pitch, a.pitch_rate, b.pitch_rate);
    // Sideways motion and yaw are slow (the guides' play): linear between the steps.
    p.y = a.y + s * (b.y - a.y);
    p.yaw = a.yaw + s * (b.yaw - a.yaw);
    const double noise = sensor_.noise > 0.0 ? sensor_.noise * unit_normal_(rng_) : 0.0;
    HallSample sample;
    sample.t_us = static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::llround(clock * 1e6)) &
                                             0xffffffffu);
    sample.adc = adc_code(voltage(field_along_axis(p)) + noise);
    emit(sample);
  };
  if (first_) {
    first_ = false;
    if (a.t <= 0.0) take(0);
  }
  while (true_time(next_index_) <= b.t + 1e-12 * interval_) {
    take(next_index_);
    ++next_index_;
  }
}

}  // namespace fl
