// The first question asked of another instrument's channel: does it show a periodic motion at
// all? Against signals with a known answer: a swing buried in noise as large as itself, a
// magnet's pulses passing a phone, are periodic and their strongest frequency is theirs; noise,
// a slow drift, and a phone lying still in a file are not, and the file is refused with what was
// found.
#include "hall_log/periodic_motion.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"

namespace fl {
namespace {

Series sampled(double rate_hz, double seconds, auto value) {
  Series s;
  for (int k = 0; k < static_cast<int>(rate_hz * seconds); ++k) {
    s.t_s.push_back(k / rate_hz);
    s.values.push_back(value(k / rate_hz));
    s.lines.push_back(k + 2);
  }
  return s;
}

TEST(PeriodicMotion, ASwingAsLargeAsItsNoiseIsPeriodic) {
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Periodicity p = periodicity_of(sampled(100.0, 30.0, [&](double t) {
    return std::sin(2.0 * std::numbers::pi * t / 0.7766) + noise(random);
  }));
  EXPECT_TRUE(p.periodic()) << p.peak_over_median;
  EXPECT_NEAR(p.strongest_hz, 1.0 / 0.7766, 0.02);
  EXPECT_NEAR(p.noise, 1.0, 0.1);
}

TEST(PeriodicMotion, AMagnetsPulsesArePeriodic) {
  std::mt19937 random(4);
  std::normal_distribution<double> noise(0.0, 0.15);
  const Periodicity p = periodicity_of(sampled(100.0, 30.0, [&](double t) {
    const double phase = std::remainder(t, 1.2345) / 0.03;  // a 30 ms pulse each period
    return 48.0 + 20.0 * std::exp(-phase * phase) + noise(random);
  }));
  EXPECT_TRUE(p.periodic()) << p.peak_over_median;
  // The fundamental or one of its harmonics.
  const double harmonic = p.strongest_hz * 1.2345;
  EXPECT_NEAR(harmonic, std::round(harmonic), 0.03) << p.strongest_hz;
}

TEST(PeriodicMotion, NoiseAndDriftAreNot) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 0.02);
    const Periodicity p =
        periodicity_of(sampled(400.0, 30.0, [&](double) { return 9.81 + noise(random); }));
    EXPECT_FALSE(p.periodic()) << seed << ": " << p.peak_over_median;
    const Periodicity drifting = periodicity_of(
        sampled(100.0, 30.0, [&](double t) { return 45.0 + 0.2 * t + noise(random); }));
    EXPECT_FALSE(drifting.periodic()) << seed << ": " << drifting.peak_over_median;
  }
}

TEST(PeriodicMotion, APhoneLyingStillIsRefusedWithWhatWasFound) {
  std::mt19937 random(9);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::string csv =
      "\"Time (s)\",\"Acceleration x (m/s^2)\",\"Acceleration y (m/s^2)\",\"Acceleration z "
      "(m/s^2)\"\n";
  for (int k = 0; k < 12000; ++k)
    csv += fmt::format("{:.6E},{:.6E},{:.6E},{:.6E}\n", k / 400.0, noise(random), noise(random),
                       9.81 + noise(random));
  try {
    parse_hall_log(csv, "still.csv");
    FAIL() << "a phone lying still gave a log";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("still.csv:1: error: expected a periodic motion, found none in the "
                         "phyphox accelerometer's",
                         0),
              0u)
        << what;
    EXPECT_NE(what.find("its strongest frequency, "), std::string::npos) << what;
    EXPECT_NE(what.find("its noise is 0.02"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace fl
