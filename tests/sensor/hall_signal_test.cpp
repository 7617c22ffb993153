// The simulated Hall sensor against the dipole formula, the ADC's transfer, and its clock.
#include "sensor/hall_signal.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sensor/dipole_field.hpp"

namespace fl {
namespace {

TEST(DipoleField, OnAxisAndOnTheEquator) {
  const Vec3 m{0.0, 0.0, 0.08};  // A m^2 along z
  const double r = 0.01;
  // On the axis: B = mu0/(4 pi) 2 m / r^3 along m; on the equator: -mu0/(4 pi) m / r^3.
  const Vec3 axis = dipole_field(m, {0, 0, 0}, {0, 0, r});
  EXPECT_NEAR(axis[2], 1e-7 * 2 * 0.08 / (r * r * r), 1e-9);
  EXPECT_NEAR(axis[0], 0.0, 1e-15);
  const Vec3 equator = dipole_field(m, {0, 0, 0}, {r, 0, 0});
  EXPECT_NEAR(equator[2], -1e-7 * 0.08 / (r * r * r), 1e-9);
  // Falls off as 1/r^3.
  const Vec3 far = dipole_field(m, {0, 0, 0}, {0, 0, 2 * r});
  EXPECT_NEAR(axis[2] / far[2], 8.0, 1e-12);
}

TEST(DipoleField, MomentOfACylinderMagnet) {
  MagnetDesc magnet;
  magnet.diameter = 0.006;
  magnet.thickness = 0.003;
  magnet.remanence = 1.2;
  // Br V / mu0 = 1.2 * pi * 9e-6 * 3e-3 / (4 pi 1e-7) = 0.0810 A m^2
  EXPECT_NEAR(magnet_moment(magnet), 1.2 * std::numbers::pi * 9e-6 * 3e-3 / kMu0, 1e-12);
}

Scene sensed_scene() {
  Scene s;
  s.magnets = {MagnetDesc{}};
  s.magnets[0].x = 0.095;
  SensorDesc sensor;
  sensor.position = {0.095, 0.0, 0.015};
  sensor.noise = 0.0;
  sensor.jitter = 0.0;
  s.sensor = sensor;
  return s;
}

TEST(HallSignal, FieldUnderTheMagnetAndTheAdcTransfer) {
  const Scene s = sensed_scene();
  HallSignal hall(compile_rig(s));
  const PlateMass pm = plate_mass(s);
  // Plate centred: the magnet's centre is straight below the sensor.
  PlatePose pose;
  pose.x = pm.x_c;
  pose.z = pm.h_c;
  const double magnet_z = s.plate.thickness + 0.5 * s.magnets[0].thickness;
  const double r = 0.015 - magnet_z;
  const double expected = 1e-7 * 2.0 * magnet_moment(s.magnets[0]) / (r * r * r);
  EXPECT_NEAR(hall.field_along_axis(pose), expected, 1e-6 * expected);
  // A TinkerKit-style module: 2.5 V at zero field, 25 V/T, 10 bits over 5 V.
  EXPECT_DOUBLE_EQ(hall.voltage(0.0), 2.5);
  EXPECT_EQ(hall.adc_code(2.5), 512);
  EXPECT_EQ(hall.adc_code(-1.0), 0);  // clipped at the rails
  EXPECT_EQ(hall.adc_code(6.0), 1023);
  EXPECT_EQ(hall.adc_code(4.99999), 1023);
}

// The whole pose: a plate moved 4 mm sideways and turned 0.2 rad about z (and pitched) puts its
// magnet where the plate's rotation carries it; the field there is the dipole formula's,
// B = mu0 / (4 pi) (3 (m . r^) r^ - m) / r^3, evaluated here by hand at the sensor.
TEST(HallSignal, FieldFollowsTheSidewaysPositionYawAndPitch) {
  Scene s = sensed_scene();
  s.sensor->axis = {0.3, -0.2, 1.0};
  HallSignal hall(compile_rig(s));
  const PlateMass pm = plate_mass(s);
  PlatePose pose;
  pose.x = pm.x_c + 0.002;
  pose.y = 0.004;
  pose.z = pm.h_c + 0.0005;
  pose.yaw = 0.2;
  pose.pitch = 0.01;
  // The magnet's centre in the plate's frame (from the centre of mass), turned by the pitch about
  // y and then the yaw about z.
  const double ox = s.magnets[0].x - pm.x_c;
  const double oz = s.plate.thickness + 0.5 * s.magnets[0].thickness - pm.h_c;
  const double cp = std::cos(pose.pitch), sp = std::sin(pose.pitch);
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  const double px = ox * cp + oz * sp;
  const double magnet[3] = {pose.x + px * cy, pose.y + px * sy, pose.z - ox * sp + oz * cp};
  const double moment = magnet_moment(s.magnets[0]);
  const double m[3] = {moment * sp * cy, moment * sp * sy, moment * cp};
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = s.sensor->position[i] - magnet[i];
  const double d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  const double m_dot_r = (m[0] * r[0] + m[1] * r[1] + m[2] * r[2]) / d;
  const double norm = std::sqrt(0.3 * 0.3 + 0.2 * 0.2 + 1.0);
  const double axis[3] = {0.3 / norm, -0.2 / norm, 1.0 / norm};
  double expected = 0.0;
  for (int i = 0; i < 3; ++i)
    expected += 1e-7 * (3.0 * m_dot_r * r[i] / d - m[i]) / (d * d * d) * axis[i];
  EXPECT_NEAR(hall.field_along_axis(pose), expected, 1e-9 * std::fabs(expected));
  // Sideways, the magnet is farther from the sensor: a weaker field than centred.
  PlatePose centred = pose;
  centred.y = 0.0;
  centred.yaw = 0.0;
  EXPECT_LT(std::fabs(hall.field_along_axis(pose)), std::fabs(hall.field_along_axis(centred)));
}

TEST(HallSignal, SamplesFollowTheAdcClockNotThePhysicsStep) {
  Scene s = sensed_scene();
  s.sensor->sample_rate = 1000.0;
  HallSignal hall(compile_rig(s));
  std::vector<HallSample> samples;
  // Physics steps of 3.7 ms: the samples still come every 1 ms, stamped on the clock.
  PlatePose a, b;
  a.z = b.z = plate_mass(s).h_c;
  for (int i = 0; i < 100; ++i) {
    a.t = i * 0.0037;
    b.t = (i + 1) * 0.0037;
    hall.sample_between(a, b, [&](const HallSample& x) { samples.push_back(x); });
  }
  ASSERT_EQ(samples.size(), 371u);  // t = 0, 1, ..., 370 ms
  for (std::size_t i = 0; i < samples.size(); ++i) EXPECT_EQ(samples[i].t_us, i * 1000u);
}

TEST(HallSignal, SameSeedSameNoiseOtherSeedOtherNoise) {
  const auto run = [](std::uint64_t seed) {
    Scene s = sensed_scene();
    s.sensor->noise = 0.01;
    s.sensor->jitter = 20e-6;
    s.world.seed = seed;
    HallSignal hall(compile_rig(s));
    std::vector<int> codes;
    PlatePose a, b;
    a.z = b.z = plate_mass(s).h_c;
    b.t = 0.2;
    hall.sample_between(a, b, [&](const HallSample& x) { codes.push_back(x.adc); });
    return codes;
  };
  EXPECT_EQ(run(1), run(1));
  EXPECT_NE(run(1), run(2));
}

}  // namespace
}  // namespace fl
