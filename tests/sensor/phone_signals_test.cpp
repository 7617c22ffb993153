// A phone's sensors against independent truth: the axes of a phone lying turned on a table, the
// dipole's field on its axis and the Earth's beside it, a still phone reading g (and g's
// projection on a pitched plate), a plate moving harmonically read as -omega^2 x, the phone's
// own clock, and its noise's spread.
#include "sensor/phone_signals.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sensor/dipole_field.hpp"

namespace fl {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PhoneAxes, APhoneLyingTurnedSeesTheRigsAxesTurnedBack) {
  // Top toward +x: the rig's x is the phone's y, the rig's y its -x (its screen's left).
  const Vec3 x0 = in_phone_axes({1.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(x0[0], 0.0, 1e-15);
  EXPECT_NEAR(x0[1], 1.0, 1e-15);
  const Vec3 y0 = in_phone_axes({0.0, 1.0, 0.0}, 0.0);
  EXPECT_NEAR(y0[0], -1.0, 1e-15);
  // Top toward +y (turned 90 deg): the rig's y is the phone's y, its x the phone's x.
  const Vec3 x90 = in_phone_axes({1.0, 0.0, 0.0}, kPi / 2);
  EXPECT_NEAR(x90[0], 1.0, 1e-15);
  EXPECT_NEAR(x90[1], 0.0, 1e-15);
  // Turned 30 deg: the rig's x lies 30 deg from the phone's y; z is untouched; lengths kept.
  const Vec3 v = in_phone_axes({0.3, -0.4, 1.2}, kPi / 6);
  EXPECT_NEAR(std::hypot(v[0], v[1], v[2]), std::hypot(0.3, -0.4, 1.2), 1e-15);
  EXPECT_NEAR(in_phone_axes({1.0, 0.0, 0.0}, kPi / 6)[1], std::cos(kPi / 6), 1e-15);
  EXPECT_DOUBLE_EQ(v[2], 1.2);
}

Scene plate_with_magnet() {
  Scene s;
  s.magnets = {MagnetDesc{}};
  s.magnets[0].x = 0.0;
  return s;
}

PlatePose centred(const PlateMass& pm) {
  PlatePose pose;
  pose.x = pm.x_c;
  pose.z = pm.h_c;
  return pose;
}

TEST(PhoneMagnetometer, ReadsTheEarthAndTheMagnetBelowItOnItsAxis) {
  Scene s = plate_with_magnet();
  PhoneDesc phone;
  phone.noise = 0.0;
  phone.position = {0.0, 0.0, 0.050};  // straight above the magnet, 50 mm up
  phone.earth = {21e-6, -4e-6, -43e-6};
  s.phones = {phone};
  const CompiledRig rig = compile_rig(s);
  const PhoneSignal signal(rig, 0);
  const double magnet_z = s.plate.thickness + 0.5 * s.magnets[0].thickness;
  const double r = 0.050 - magnet_z;
  // On the dipole's axis: mu0 / (4 pi) 2 m / r^3, along z.
  const double pulse = 1e-7 * 2.0 * magnet_moment(s.magnets[0]) / (r * r * r);
  const Vec3 b = signal.magnetic_field(centred(plate_mass(s)));
  EXPECT_NEAR(b[2], -43e-6 + pulse, 1e-9 * pulse);
  // The phone's top toward +x: the Earth's x in its y, the Earth's y in its -x.
  EXPECT_NEAR(b[1], 21e-6, 1e-12);
  EXPECT_NEAR(b[0], 4e-6, 1e-12);
}

TEST(PhoneMagnetometer, FarFromTheMagnetsItReadsTheEarthTurnedWithThePhone) {
  Scene s = plate_with_magnet();
  PhoneDesc phone;
  phone.noise = 0.0;
  phone.position = {100.0, 100.0, 0.0};  // 141 m away: the magnet's field is 1e-14 T there
  phone.turn = kPi / 2;                  // top toward +y
  s.phones = {phone};
  const Vec3 b = PhoneSignal(compile_rig(s), 0).magnetic_field(centred(plate_mass(s)));
  EXPECT_NEAR(b[0], 21e-6, 1e-13);
  EXPECT_NEAR(b[1], -4e-6, 1e-13);
  EXPECT_NEAR(b[2], -43e-6, 1e-13);
}

Scene plate_with_phone(bool gravity) {
  Scene s;
  PhoneDesc phone;
  phone.sensor = PhoneSensor::kAccelerometer;
  phone.noise = 0.0;
  phone.gravity = gravity;
  phone.rate = 400.0;
  s.phones = {phone};
  return s;
}

TEST(PhoneAccelerometer, AStillPhoneReadsGUpOrNothing) {
  for (const bool gravity : {true, false}) {
    const Scene s = plate_with_phone(gravity);
    const Vec3 a =
        PhoneSignal(compile_rig(s), 0).acceleration(centred(plate_mass(s)), PlateAcceleration{});
    EXPECT_NEAR(a[0], 0.0, 1e-12);
    EXPECT_NEAR(a[1], 0.0, 1e-12);
    EXPECT_NEAR(a[2], gravity ? s.world.gravity : 0.0, 1e-12);
  }
}

TEST(PhoneAccelerometer, OnAPitchedPlateGravityLeansIntoItsLength) {
  // Pitched by +0.1 rad about +y, the plate's +x end is lower: the phone (top toward +x) reads
  // -g sin(0.1) along its y and g cos(0.1) along z.
  const Scene s = plate_with_phone(true);
  PlatePose pose = centred(plate_mass(s));
  pose.pitch = 0.1;
  const Vec3 a = PhoneSignal(compile_rig(s), 0).acceleration(pose, PlateAcceleration{});
  EXPECT_NEAR(a[1], -s.world.gravity * std::sin(0.1), 1e-12);
  EXPECT_NEAR(a[2], s.world.gravity * std::cos(0.1), 1e-12);
  EXPECT_NEAR(a[0], 0.0, 1e-12);
}

TEST(PhoneAccelerometer, AHarmonicPlateIsReadAsMinusOmegaSquaredXAtThePhonesClock) {
  const Scene s = plate_with_phone(false);
  const PlateMass pm = plate_mass(s);
  PhoneSignal signal(compile_rig(s), 0);
  // x = A cos(omega t) stepped at 1 ms with exact velocities; the phone samples at 400 Hz.
  const double amplitude = 0.03, omega = 2 * kPi / 0.78, h = 1e-3;
  const auto state = [&](double t) {
    PlatePose p;
    p.t = t;
    p.x = pm.x_c + amplitude * std::cos(omega * t);
    p.vx = -amplitude * omega * std::sin(omega * t);
    p.z = pm.h_c;
    return p;
  };
  std::vector<PhoneSample> samples;
  for (int k = 0; k < 2000; ++k)
    signal.sample_between(state(k * h), state((k + 1) * h),
                          [&](const PhoneSample& p) { samples.push_back(p); });
  ASSERT_EQ(samples.size(), 801u);  // 2 s at 400 Hz, t = 0 included
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].t, static_cast<double>(i) / 400.0, 1e-12);
    // Each sample carries its step's mean acceleration: within the change over half a step
    // (A omega^3 h / 2) of -omega^2 x at the sample's time.
    const double expected = -omega * omega * amplitude * std::cos(omega * samples[i].t);
    EXPECT_NEAR(samples[i].value[1], expected, amplitude * std::pow(omega, 3) * h * 0.5 + 1e-9)
        << samples[i].t;
  }
}

TEST(PhoneNoise, EachAxisScattersByTheNoiseAndTwoPhonesDiffer) {
  Scene s = plate_with_phone(true);
  s.phones[0].noise = 0.05;
  s.phones.push_back(s.phones[0]);
  const CompiledRig rig = compile_rig(s);
  PhoneSignal first(rig, 0), second(rig, 1);
  PlatePose a = centred(rig.plate), b = a;
  b.t = 100.0;  // 40 001 samples of a still phone
  double sum = 0.0, sum2 = 0.0;
  int n = 0, equal = 0;
  std::vector<double> z;
  first.sample_between(a, b, [&](const PhoneSample& p) {
    const double e = p.value[0];
    sum += e;
    sum2 += e * e;
    ++n;
    z.push_back(p.value[2]);
  });
  std::size_t i = 0;
  second.sample_between(a, b, [&](const PhoneSample& p) { equal += p.value[2] == z[i++]; });
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  // The sample deviation of 40 001 normal draws lies within 2 % of sigma (5 standard errors).
  EXPECT_NEAR(sd, 0.05, 0.05 * 0.02);
  EXPECT_NEAR(mean, 0.0, 5 * 0.05 / std::sqrt(n));
  EXPECT_EQ(equal, 0);  // their own noise, not one stream twice
}

}  // namespace
}  // namespace fl
