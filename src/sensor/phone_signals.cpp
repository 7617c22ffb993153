#include "sensor/phone_signals.hpp"

#include <cmath>
#include <cstdint>

namespace fl {
namespace {

// SplitMix64's finaliser: a 64-bit seed for phone `index` from the run's, far from both.
std::uint64_t phone_seed(std::uint64_t seed, std::size_t index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(index) + 1) +
                    0x70686f6e65ULL;  // "phone"
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

Vec3 in_phone_axes(const Vec3& v, double turn) {
  const double c = std::cos(turn), s = std::sin(turn);
  // The phone's y = (c, s, 0) and x = (s, -c, 0) in the frame of v.
  return {v[0] * s - v[1] * c, v[0] * c + v[1] * s, v[2]};
}

PhoneSignal::PhoneSignal(const CompiledRig& rig, std::size_t index)
    : phone_(rig.phones.at(index)),
      magnets_(rig),
      clock_(phone_.rate),
      noise_(phone_seed(rig.world.seed, index)) {
  const double g = rig.world.gravity;
  gravity_ = {-g * std::sin(rig.contact_tilt), 0.0, -g * std::cos(rig.contact_tilt)};
  offset_on_plate_ = {
      phone_.x - rig.plate.x_c, 0.0,
      rig.plate_desc.thickness + phone_.height + 0.5 * phone_.size[2] - rig.plate.h_c};
}

Vec3 PhoneSignal::magnetic_field(const PlatePose& pose) const {
  const Vec3 b = magnets_.field(pose, phone_.position);
  return in_phone_axes({phone_.earth[0] + b[0], phone_.earth[1] + b[1], phone_.earth[2] + b[2]},
                       phone_.turn);
}

Vec3 PhoneSignal::acceleration(const PlatePose& pose, const PlateAcceleration& a) const {
  const double c = std::cos(pose.pitch), s = std::sin(pose.pitch);
  // The phone's centre from the plate's centre of mass, turned with the plate (about +y).
  const double rx = offset_on_plate_[0] * c + offset_on_plate_[2] * s;
  const double rz = -offset_on_plate_[0] * s + offset_on_plate_[2] * c;
  // A point of a body turning about y at q with angular acceleration alpha:
  // a_cm + alpha x r - q^2 r.
  const double q2 = pose.pitch_rate * pose.pitch_rate;
  Vec3 f{a.x + a.pitch * rz - q2 * rx, 0.0, a.z - a.pitch * rx - q2 * rz};
  if (phone_.gravity)
    for (std::size_t k = 0; k < 3; ++k) f[k] -= gravity_[k];
  // Into the plate's frame: undo the yaw about +z, then the pitch about +y.
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  const Vec3 unyawed{f[0] * cy + f[1] * sy, -f[0] * sy + f[1] * cy, f[2]};
  const Vec3 on_plate{unyawed[0] * c - unyawed[2] * s, unyawed[1], unyawed[0] * s + unyawed[2] * c};
  return in_phone_axes(on_plate, phone_.turn);
}

void PhoneSignal::sample_between(const PlatePose& a, const PlatePose& b,
                                 const std::function<void(const PhoneSample&)>& emit) {
  const double h = b.t - a.t;
  if (!(h > 0.0)) return;
  const PlateAcceleration step{(b.vx - a.vx) / h, (b.vz - a.vz) / h,
                               (b.pitch_rate - a.pitch_rate) / h};
  const bool magnetometer = phone_.sensor == PhoneSensor::kMagnetometer;
  const auto take = [&](long long index) {
    PhoneSample sample;
    sample.t = clock_.true_time(index);
    const PlatePose p = pose_between(a, b, sample.t);
    sample.value = magnetometer ? magnetic_field(p) : acceleration(p, step);
    if (phone_.noise > 0.0)
      for (double& axis : sample.value) axis += phone_.noise * noise_.standard();
    emit(sample);
  };
  clock_.due(a.t, b.t, take);
}

}  // namespace fl
