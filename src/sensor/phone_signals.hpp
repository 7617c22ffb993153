// A phone's sensors as phyphox records them, sampled at the phone's own rate between the physics
// steps: the magnetometer of a phone lying beside the rig (the Earth's field and the plate's
// magnets, point dipoles as the Hall sensor sees them) and the accelerometer of a phone lying on
// the plate (the plate's acceleration at the phone, with or without g). Each reading is in the
// phone's axes (scene/scene.hpp, PhoneDesc), with white noise on each axis.
#pragma once

#include <cstddef>
#include <functional>

#include "core/normal_draws.hpp"
#include "scene/compiled_rig.hpp"
#include "sensor/plate_magnets.hpp"
#include "sensor/plate_pose.hpp"
#include "sensor/sample_clock.hpp"

namespace fl {

struct PhoneSample {
  double t = 0.0;  // s, the phone's time stamp (its clock is the run's)
  Vec3 value{};    // T (magnetometer) or m/s^2 (accelerometer), in the phone's axes
};

// A vector of the rig's frame (or the plate's) in the axes of a phone lying flat, screen up, its
// top turned `turn` [rad] from +x about +z: y toward its top, x to the screen's right, z up.
Vec3 in_phone_axes(const Vec3& v, double turn);

// What the plate does over one physics step, for a phone riding on it: its centre of mass's
// acceleration [m/s^2, world frame] and its pitch's angular acceleration [rad/s^2], each the
// step's mean (the change of the rates over the step).
struct PlateAcceleration {
  double x = 0.0, z = 0.0;  // m/s^2
  double pitch = 0.0;       // rad/s^2
};

class PhoneSignal {
 public:
  // Phone `index` of the rig's phones. Its noise comes from world.seed and the index: a stream
  // of its own, not the Hall sensor's nor another phone's.
  PhoneSignal(const CompiledRig& rig, std::size_t index);

  // The noiseless magnetometer [T, phone axes] with the plate at `pose`.
  Vec3 magnetic_field(const PlatePose& pose) const;
  // The noiseless accelerometer [m/s^2, phone axes] with the plate at `pose` accelerating by `a`:
  // the acceleration at the phone's centre, less g when the phone records it (its "Acceleration":
  // a phone lying still reads +g along z).
  Vec3 acceleration(const PlatePose& pose, const PlateAcceleration& a) const;

  // Emits, in time order, every sample whose time falls in (a.t, b.t] (and t = 0 on the first
  // call), the plate's pose interpolated between the two physics states.
  void sample_between(const PlatePose& a, const PlatePose& b,
                      const std::function<void(const PhoneSample&)>& emit);

 private:
  PhoneDesc phone_;
  PlateMagnets magnets_;
  Vec3 gravity_{};        // m/s^2, in the world's frame (the contact line's)
  Vec3 offset_on_plate_;  // m, the phone's centre from the plate's centre of mass, plate frame
  SampleClock clock_;     // the phone's clock is the run's
  // Its noise: the same bits on every standard library (core/normal_draws.hpp).
  NormalDraws noise_;
};

}  // namespace fl
