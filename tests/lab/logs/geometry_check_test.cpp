// The geometry a log shows, checked on synthetic logs whose sensor position is known: evenly
// spaced pulses from a magnet turning at the sensor pass the check; from a magnet passing a
// sensor at the exact middle of its travel, or a little off it (the periods alternate), or too
// few samples across a pulse, or clipped pulses, the check says the log cannot tell and asks
// for --geometry; following that advice gives the true period.
#include "lab/logs/geometry_check.hpp"
#include "cli/field_spelling.hpp"

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "estimator/synthetic_hall.hpp"
#include "io/input_error.hpp"

namespace fl {
namespace {

HallLog log_of(const test::HallSignal& s) {
  const test::HallSamples g = test::generate(s);
  std::string text = "t_us,adc\n";
  char line[64];
  for (std::size_t i = 0; i < g.adc.size(); ++i) {
    std::snprintf(line, sizeof line, "%u,%u\n", g.t_us[i], g.adc[i]);
    text += line;
  }
  return parse_hall_log(text, "hall.csv");
}

struct Checked {
  LogEstimate estimate;
  GeometryCheck check;
  std::string error;  // require_geometry's message, "" when none
};

Checked check(const test::HallSignal& s, fl_estimator::Geometry geometry) {
  const HallLog log = log_of(s);
  LogSetUp set_up;
  set_up.geometry = geometry;
  Checked c{estimate_log(log, set_up, false), {}, ""};
  c.check = check_geometry(log, c.estimate);
  try {
    require_geometry(log, c.estimate, c.check, "");
  } catch (const InputError& e) {
    c.error = cli::spelled(e.what());
  }
  return c;
}

test::HallSignal signal(double offset_m, double height_m, double rate_hz, double noise) {
  test::HallSignal s;
  s.sensor_offset_m = offset_m;
  s.magnet_height_m = height_m;
  s.sample_rate_hz = rate_hz;
  s.noise_counts = noise;
  s.jitter_us = noise > 0.0 ? 0.1e6 / rate_hz : 0.0;
  s.duration_s = 12.0;
  return s;
}

// One pulse per period: the sensor 0 to 6 mm beyond the turning point, the magnet 4 to 16 mm
// from it, 200 Hz to 10 kHz, with and without noise.
TEST(GeometryCheck, AMagnetTurningAtTheSensorPassesIt) {
  for (double rate : {200.0, 1000.0, 10000.0})
    for (double height : {0.004, 0.008, 0.012, 0.016})
      for (double offset : {0.0, 0.003, 0.006})
        for (double noise : {0.0, 2.0}) {
          if (height == 0.004 && offset == 0.006) continue;  // too weak to be a pulse
          const test::HallSignal s = signal(offset, height, rate, noise);
          const Checked c = check(s, fl_estimator::kAutoGeometry);
          const std::string at = "rate " + std::to_string(rate) + " height " +
                                 std::to_string(height) + " offset " + std::to_string(offset) +
                                 " noise " + std::to_string(noise);
          ASSERT_EQ(c.estimate.geometry, fl_estimator::kOnePulse) << at;
          EXPECT_TRUE(c.check.needed) << at;
          EXPECT_EQ(c.check.verdict, "turn") << at << ": " << c.check.reason;
          EXPECT_LT(*c.check.shape_ratio, 1.40) << at;
          EXPECT_FALSE(c.check.alternates) << at;
          EXPECT_EQ(c.error, "") << at;
          EXPECT_NEAR(c.estimate.stats.period_s, s.period_s, 5e-4 * s.period_s) << at;
        }
}

// The sensor at the exact middle of the travel: the pulses are evenly spaced, at T/2, and shaped
// like a pass; the check refuses T/2 and names both options, and the pair it names reads T.
TEST(GeometryCheck, AMagnetPassingAtTheMiddleOfTheTravelIsNotTakenForOnePulse) {
  for (double rate : {200.0, 1000.0, 10000.0})
    for (double height : {0.004, 0.008, 0.012, 0.016})
      for (double noise : {0.0, 2.0}) {
        test::HallSignal s = signal(0.0, height, rate, noise);
        s.sensor_offset_m = -s.amplitude_m;
        const std::string at = "rate " + std::to_string(rate) + " height " +
                               std::to_string(height) + " noise " + std::to_string(noise);
        const Checked c = check(s, fl_estimator::kAutoGeometry);
        ASSERT_EQ(c.estimate.geometry, fl_estimator::kOnePulse) << at;
        EXPECT_NEAR(c.estimate.stats.period_s, 0.5 * s.period_s, 5e-4 * s.period_s) << at;
        EXPECT_EQ(c.check.verdict, "pass") << at << ": " << c.check.reason;
        EXPECT_GT(*c.check.shape_ratio, 1.44) << at;
        EXPECT_EQ(c.error.rfind("hall.csv:", 0), 0u) << c.error;
        EXPECT_NE(c.error.find("pulses at even intervals of 0.3950 s"), std::string::npos)
            << c.error;
        EXPECT_NE(c.error.find("--geometry pair for one at the middle"), std::string::npos)
            << c.error;
        EXPECT_NE(c.error.find("--geometry one"), std::string::npos) << c.error;
        const Checked pair = check(s, fl_estimator::kPulsePair);
        EXPECT_FALSE(pair.check.needed);
        EXPECT_EQ(pair.error, "");
        EXPECT_NEAR(pair.estimate.stats.period_s, s.period_s, 5e-4 * s.period_s) << at;
      }
}

// Half a millimetre off the middle of a 20 mm travel: the intervals differ by 3 %, too little
// for the estimator's look at five pulses (4 %), but the periods alternate over the log.
TEST(GeometryCheck, PeriodsThatAlternateAreTwoPulsesPerPeriod) {
  for (double noise : {0.0, 2.0}) {
    test::HallSignal s = signal(0.0, 0.008, 1000.0, noise);
    s.sensor_offset_m = -s.amplitude_m + 0.0005;
    const Checked c = check(s, fl_estimator::kAutoGeometry);
    ASSERT_EQ(c.estimate.geometry, fl_estimator::kOnePulse);
    EXPECT_TRUE(c.check.alternates);
    EXPECT_EQ(c.check.verdict, "alternating");
    // Each interval is 2 arcsin(d/A)/pi of T/2 off the mean of its neighbours, by turns.
    const double expected = 2.0 * std::asin(0.0005 / s.amplitude_m) / test::kPiTest * s.period_s;
    EXPECT_NEAR(std::fabs(*c.check.alternation_s), expected, 0.05 * expected);
    EXPECT_NE(c.error.find("the periods alternate short and long"), std::string::npos) << c.error;
    const Checked pair = check(s, fl_estimator::kPulsePair);
    EXPECT_NEAR(pair.estimate.stats.period_s, s.period_s, 5e-4 * s.period_s);
  }
}

// The alternation's floor: the periods read alternate by (2/pi) arcsin(d/A) of the true period,
// and the check needs 0.05 % of the period read (T/2), which a quiet signal reaches from d of
// about 0.04 % of A: found at 0.045 % (9 micrometres of a 20 mm amplitude), not at 0.03 %.
TEST(GeometryCheck, TheAlternationIsFoundDownToFourHundredthsOfAPercentOfTheAmplitude) {
  for (const double share : {0.00045, 0.0003}) {
    test::HallSignal s = signal(0.0, 0.008, 1000.0, 0.0);
    s.duration_s = 30.0;
    s.sensor_offset_m = -s.amplitude_m + share * s.amplitude_m;
    const Checked c = check(s, fl_estimator::kAutoGeometry);
    ASSERT_EQ(c.estimate.geometry, fl_estimator::kOnePulse) << share;
    EXPECT_EQ(c.check.alternates, share > 0.0004) << share;
  }
}

TEST(GeometryCheck, PulsesTooNarrowOrClippedCannotTell) {
  // 50 Hz: a turning pulse spans 3 samples at half its height.
  test::HallSignal narrow = signal(0.003, 0.004, 50.0, 0.0);
  const Checked n = check(narrow, fl_estimator::kAutoGeometry);
  ASSERT_EQ(n.estimate.geometry, fl_estimator::kOnePulse);
  EXPECT_EQ(n.check.verdict, "unknown");
  EXPECT_NE(n.error.find("too few to tell a turn from a pass"), std::string::npos) << n.error;
  EXPECT_NEAR(check(narrow, fl_estimator::kOnePulse).estimate.stats.period_s, narrow.period_s,
              5e-4 * narrow.period_s);
  // A strong magnet: the pulses clipped at the 10-bit ADC's top.
  test::HallSignal clipped = signal(0.003, 0.008, 1000.0, 0.0);
  clipped.peak_counts = 2000.0;
  const Checked c = check(clipped, fl_estimator::kAutoGeometry);
  ASSERT_EQ(c.estimate.geometry, fl_estimator::kOnePulse);
  EXPECT_TRUE(c.check.clipped);
  EXPECT_EQ(c.check.verdict, "unknown");
  EXPECT_NE(c.error.find("clipped at the ADC's rail"), std::string::npos) << c.error;
}

TEST(GeometryCheck, AGivenGeometryAndARecognisedPairNeedNoCheck) {
  const test::HallSignal one = signal(0.003, 0.008, 1000.0, 0.0);
  EXPECT_FALSE(check(one, fl_estimator::kOnePulse).check.needed);
  const test::HallSignal pair = signal(-0.010, 0.008, 1000.0, 0.0);
  const Checked c = check(pair, fl_estimator::kAutoGeometry);
  EXPECT_EQ(c.estimate.geometry, fl_estimator::kPulsePair);
  EXPECT_FALSE(c.check.needed);
  EXPECT_EQ(c.error, "");
}

}  // namespace
}  // namespace fl
