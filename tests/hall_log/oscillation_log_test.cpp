// An oscillation followed by another instrument, read back through the rig's estimator: a plate
// moving as x(t) = A cos(2 pi t / T + phase) with a known T, seen by Tracker at a phone video's 30
// and 60 frames a second (clicks scattered by half a millimetre), written as a spreadsheet's table
// in another unit and form, and felt by a phone on the plate (a = -(2 pi / T)^2 x, g on another
// axis, at 400 Hz with noise). T comes back within 0.05 % from each, the same numbers give the same
// T in every form, and the column read is the one the plate moves along.
#include "hall_log/oscillation_log.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {
namespace {

constexpr double kPeriod = 0.8123;    // s
constexpr double kAmplitude = 0.015;  // m
constexpr double kSeconds = 30.0;

double plate_x(double t) {
  return kAmplitude * std::cos(2.0 * std::numbers::pi * t / kPeriod + 0.4);
}

double period_of(const HallLog& log) {
  const LogEstimate e = estimate_log(log, LogSetUp{}, false);
  EXPECT_GE(e.stats.periods_used, 25u) << instrument_words(log.instrument);
  return e.stats.period_s;
}

// Tracker's exported data: the track's name, then t, x, y by tabs; each mark scattered by
// `scatter_m` (Tracker's autotracker: about 0.1 mm on a 1080p video of the rig; clicks by hand:
// about 0.5 mm); y holds the scatter only.
std::string tracker(double fps, unsigned seed, double scatter_m = 1e-4) {
  std::mt19937 random(seed);
  std::normal_distribution<double> click(0.0, scatter_m);
  std::string text = "mass A\nt\tx\ty\n";
  for (int i = 0; i < static_cast<int>(kSeconds * fps); ++i) {
    const double t = i / fps;
    const double x = plate_x(t) + click(random);
    const double y = 0.02 + click(random);
    text += fmt::format("{:.6E}\t{:.6E}\t{:.6E}\n", t, x, y);
  }
  return text;
}

TEST(OscillationLog, TrackersPositionsAtAPhoneVideosFrameRates) {
  for (double fps : {30.0, 60.0}) {
    const HallLog log = parse_hall_log(tracker(fps, 3), "mass-a.txt");
    EXPECT_EQ(instrument_words(log.instrument), "Tracker");
    EXPECT_EQ(log.channel, "x");
    EXPECT_EQ(log.reading.format, "tracker");
    EXPECT_NEAR(period_of(log), kPeriod, 5e-4 * kPeriod) << fps << " fps";
    // The positions' amplitude, in Tracker's unit (its header names none).
    std::string unit = "?";
    const std::optional<double> amplitude =
        plate_amplitude(log, estimate_log(log, LogSetUp{}, false), &unit);
    ASSERT_TRUE(amplitude.has_value());
    EXPECT_EQ(unit, "");
    EXPECT_NEAR(*amplitude, kAmplitude, 0.01 * kAmplitude);
  }
}

// Marks clicked by hand scatter five times more: T is then as good as its own standard error
// says, over seeds (within 3 of them, each time).
TEST(OscillationLog, ClickedMarksGiveTWithinItsStandardError) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const HallLog log = parse_hall_log(tracker(30.0, seed, 5e-4), "clicked.txt");
    const LogEstimate e = estimate_log(log, LogSetUp{}, false);
    ASSERT_GE(e.stats.periods_used, 25u);
    EXPECT_LT(std::fabs(double{e.stats.period_s} - kPeriod), 3.0 * double{e.stats.period_sem_s})
        << seed;
  }
}

TEST(OscillationLog, TheSameNumbersInEveryFormGiveTheSameT) {
  const HallLog tracked = parse_hall_log(tracker(60.0, 5), "mass-a.txt");
  // The same samples as a spreadsheet writes them: milliseconds and millimetres, semicolons and
  // decimal commas, a track of several (Tracker's #multi:) with a still background mark first.
  std::string sheet = "t_ms;x_mm\n";
  std::string multi = "#multi:\nbackground\tmass A\nt\tx\ty\tt\tx\ty\n";
  const std::string text = tracker(60.0, 5);
  std::size_t pos = text.find("t\tx\ty\n") + 6;
  std::mt19937 random(11);
  std::normal_distribution<double> click(0.0, 5e-4);
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::string row = text.substr(pos, end - pos);
    pos = end + 1;
    const double t = std::stod(row.substr(0, row.find('\t')));
    const double x = std::stod(row.substr(row.find('\t') + 1));
    std::string cells = fmt::format("{:.9f};{:.9f}\n", t * 1e3, x * 1e3);
    for (char& c : cells)
      if (c == '.') c = ',';
    sheet += cells;
    multi += fmt::format("{:.6E}\t{:.6E}\t{:.6E}\t{}\n", t, 0.05 + click(random), 0.01, row);
  }
  const HallLog table = parse_hall_log(sheet, "sheet.csv");
  EXPECT_EQ(instrument_words(table.instrument), "position-time table");
  EXPECT_EQ(table.channel, "x_mm");
  EXPECT_TRUE(table.reading.decimal_comma);
  const HallLog tracks = parse_hall_log(multi, "multi.txt");
  EXPECT_EQ(instrument_words(tracks.instrument), "Tracker");
  const double t_tracked = period_of(tracked);
  EXPECT_NEAR(period_of(table), t_tracked, 1e-12 * kPeriod);
  EXPECT_NEAR(period_of(tracks), t_tracked, 1e-12 * kPeriod);
}

TEST(OscillationLog, APhoneOnThePlateFeelsThePeriod) {
  for (bool with_g : {true, false}) {
    std::mt19937 random(7);
    std::normal_distribution<double> noise(0.0, 0.05);
    const double omega = 2.0 * std::numbers::pi / kPeriod;
    std::string text = with_g ? "\"Time (s)\",\"Acceleration x (m/s^2)\",\"Acceleration y "
                                "(m/s^2)\",\"Acceleration z (m/s^2)\",\"Absolute acceleration "
                                "(m/s^2)\"\n"
                              : "\"Time (s)\",\"Linear Acceleration x (m/s^2)\",\"Linear "
                                "Acceleration y (m/s^2)\",\"Linear Acceleration z (m/s^2)\","
                                "\"Absolute acceleration (m/s^2)\"\n";
    for (int i = 0; i < static_cast<int>(kSeconds * 400.0); ++i) {
      const double t = i / 400.0;
      const double ax = noise(random);
      const double ay = -omega * omega * plate_x(t) + noise(random);
      const double az = (with_g ? 9.81 : 0.0) + noise(random);
      text += fmt::format("{:.6E},{:.6E},{:.6E},{:.6E},{:.6E}\n", t, ax, ay, az,
                          std::sqrt(ax * ax + ay * ay + az * az));
    }
    const HallLog log = parse_hall_log(text, "Raw Data.csv");
    EXPECT_EQ(instrument_words(log.instrument),
              with_g ? "phyphox accelerometer" : "phyphox accelerometer (without g)");
    EXPECT_EQ(log.channel, "y");
    EXPECT_NEAR(period_of(log), kPeriod, 5e-4 * kPeriod) << with_g;
    // The amplitude as a / omega^2, the axis's sinusoid fitted (its 0.05 m/s^2 of noise on a swing
    // of 0.9 m/s^2 averages out).
    std::string unit;
    const std::optional<double> amplitude =
        plate_amplitude(log, estimate_log(log, LogSetUp{}, false), &unit);
    ASSERT_TRUE(amplitude.has_value());
    EXPECT_EQ(unit, "m");
    EXPECT_NEAR(*amplitude, kAmplitude, 0.01 * kAmplitude);
  }
}

// A phone lying turned on the plate, its top 40 deg from the motion: each horizontal axis feels a
// share of it (cos 40 deg on y, sin 40 deg on x). The axes are read combined along the motion
// (their covariance's principal direction): the plate's whole amplitude, not one axis's share, and
// the aligned phone's period.
TEST(OscillationLog, APhoneLyingTurnedIsReadAlongTheMotion) {
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.05);
  const double omega = 2.0 * std::numbers::pi / kPeriod, turn = 40.0 * std::numbers::pi / 180.0;
  std::string text =
      "\"Time (s)\",\"Acceleration x (m/s^2)\",\"Acceleration y (m/s^2)\",\"Acceleration z "
      "(m/s^2)\",\"Absolute acceleration (m/s^2)\"\n";
  for (int i = 0; i < static_cast<int>(kSeconds * 400.0); ++i) {
    const double t = i / 400.0;
    const double a = -omega * omega * plate_x(t);
    const double ax = std::sin(turn) * a + noise(random);
    const double ay = std::cos(turn) * a + noise(random);
    const double az = 9.81 + noise(random);
    text += fmt::format("{:.6E},{:.6E},{:.6E},{:.6E},{:.6E}\n", t, ax, ay, az,
                        std::sqrt(ax * ax + ay * ay + az * az));
  }
  const HallLog log = parse_hall_log(text, "Raw Data.csv");
  EXPECT_EQ(log.channel, "0.643 x + 0.766 y");
  EXPECT_NEAR(period_of(log), kPeriod, 5e-4 * kPeriod);
  const std::optional<double> amplitude =
      plate_amplitude(log, estimate_log(log, LogSetUp{}, false));
  ASSERT_TRUE(amplitude.has_value());
  EXPECT_NEAR(*amplitude, kAmplitude, 0.01 * kAmplitude);
}

TEST(OscillationLog, ATableWithoutAPositionIsRefusedAtItsHeader) {
  try {
    read_oscillation_log("comment\nt\tvx\n0\t1\n", "v.txt", MeasurementFile::kTracker);
    FAIL() << "a table of speeds was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("v.txt:2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected a position column"), std::string::npos);
  }
}

}  // namespace
}  // namespace fl
