// The logs people have (tests/data/logs/, generate.py there): one simulated run of the paper's rig
// (a rigid-foam plate, T = 0.3016 s by its trajectory) written as the rig firmware, arduino-cli,
// the Arduino IDE, spreadsheets and sketches write it, with a banner, garbage, a byte-order mark,
// UTF-16, decimal commas, no header, no time column, repeated times, corrupted lines and a board
// that restarted. Each gives the same T as the clean log it came from, and says what it skipped
// and left out, counted here from the files themselves; a mostly garbled log and the sensor at
// the middle of the travel give located errors, and the advice in them works.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "cli/field_spelling.hpp"
#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {
namespace {

const std::string kDir = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/data/logs/";

// The run's own period: its trajectory's, in its summary.json (the analytic thick-plate period
// is 0.3015801 s).
constexpr double kTrajectoryPeriod = 0.301574649905138;

struct Result {
  HallLog log;
  LogEstimate estimate;
  GeometryCheck check;
};

Result estimate(const std::string& name, const HallLogOptions& options = {},
                fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry) {
  LogSetUp set_up;
  set_up.geometry = geometry;
  Result r{read_hall_log(kDir + name, options), {}, {}};
  r.estimate = estimate_log(r.log, set_up, false);
  require_periods(r.log, r.estimate, "");
  r.check = check_geometry(r.log, r.estimate);
  require_geometry(r.log, r.estimate, r.check, "");
  return r;
}

std::string error_of(const std::string& name, const HallLogOptions& options = {},
                     fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry) {
  try {
    estimate(name, options, geometry);
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

std::vector<std::string> lines_of(const std::string& name) {
  std::ifstream in(kDir + name, std::ios::binary);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(LogCorpus, TheCleanLogGivesTheRunsPeriod) {
  const Result clean = estimate("clean.csv");
  EXPECT_NEAR(clean.estimate.stats.period_s, kTrajectoryPeriod, 5e-4 * kTrajectoryPeriod);
  EXPECT_EQ(clean.log.adc.size(), 1501u);
  EXPECT_EQ(clean.estimate.geometry, fl_estimator::kOnePulse);
  EXPECT_EQ(clean.check.verdict, "turn");
}

// The same samples, written otherwise: the very same T.
TEST(LogCorpus, EveryWayOfWritingTheSamplesGivesTheSameT) {
  const Result clean = estimate("clean.csv");
  HallLogOptions rate;
  rate.rate_hz = 500.0;
  struct Case {
    const char* name;
    HallLogOptions options;
  };
  for (const Case& c :
       {Case{"firmware-capture.csv", {}}, Case{"arduino-cli-banner.csv", {}}, Case{"bom.csv", {}},
        Case{"ide-timestamps.txt", {}}, Case{"decimal-comma-semicolon.csv", {}},
        Case{"utf16-tab.txt", {}}, Case{"no-header.csv", {}}, Case{"millis-sensorvalue.csv", {}},
        Case{"no-time-column.csv", rate}, Case{"board-restarted.csv", {}},
        Case{"repeated-time.csv", {}}}) {
    const Result r = estimate(c.name, c.options);
    EXPECT_EQ(r.log.adc, clean.log.adc) << c.name;
    EXPECT_EQ(r.log.t_us, clean.log.t_us) << c.name;
    EXPECT_EQ(r.estimate.stats.period_s, clean.estimate.stats.period_s) << c.name;
    EXPECT_EQ(r.estimate.stats.periods_used, clean.estimate.stats.periods_used) << c.name;
    EXPECT_EQ(r.log.reading.corrupted.count, 0) << c.name;
  }
}

TEST(LogCorpus, EachSaysHowItWasRead) {
  const Result banner = estimate("arduino-cli-banner.csv");
  // Three lines of arduino-cli's banner and one of the bytes the reset left; the firmware's
  // comment, then its header.
  EXPECT_EQ(banner.log.reading.lines_skipped, 4);
  EXPECT_EQ(banner.log.reading.header_line, 6);
  EXPECT_EQ(banner.log.reading.format, "firmware");
  EXPECT_EQ(estimate("firmware-capture.csv").log.reading.comment_lines, 2);
  EXPECT_EQ(estimate("bom.csv").log.encoding, "utf-8 with BOM");
  EXPECT_EQ(estimate("utf16-tab.txt").log.encoding, "utf-16le");
  EXPECT_TRUE(estimate("utf16-tab.txt").log.reading.decimal_comma);
  EXPECT_TRUE(estimate("ide-timestamps.txt").log.reading.ide_timestamps);
  const Result semicolon = estimate("decimal-comma-semicolon.csv");
  EXPECT_TRUE(semicolon.log.reading.decimal_comma);
  EXPECT_EQ(semicolon.log.reading.time_unit, "s");
  const Result position = estimate("no-header.csv");
  EXPECT_EQ(position.log.reading.columns_from, "position");
  EXPECT_EQ(position.log.reading.time_unit, "us");
  EXPECT_EQ(position.log.reading.time_unit_from, "inferred");
  const Result millis = estimate("millis-sensorvalue.csv");
  EXPECT_EQ(millis.log.reading.time_unit, "ms");
  EXPECT_EQ(millis.log.reading.adc_column, "sensorValue");
  const Result restarted = estimate("board-restarted.csv");
  EXPECT_EQ(restarted.log.reading.segments, 2);
  EXPECT_EQ(restarted.log.segment_samples_left_out, 200);
}

TEST(LogCorpus, RepeatedTimesAreCountedWhereTheyAre) {
  // The lines whose time repeats the line before's, found here by hand.
  const std::vector<std::string> lines = lines_of("repeated-time.csv");
  std::vector<int> repeated;
  for (std::size_t i = 2; i < lines.size(); ++i)
    if (lines[i].substr(0, lines[i].find(',')) == lines[i - 1].substr(0, lines[i - 1].find(',')))
      repeated.push_back(static_cast<int>(i) + 1);
  ASSERT_EQ(repeated.size(), 5u);
  const Result r = estimate("repeated-time.csv");
  EXPECT_EQ(r.log.reading.repeated_times.count, 5);
  EXPECT_EQ(r.log.reading.repeated_times.first, repeated);
}

TEST(LogCorpus, CorruptedLinesAreLeftOutCountedAndLocated) {
  // Lines that are not two numbers, the second an ADC value, found here by hand.
  const std::vector<std::string> lines = lines_of("corrupted-line.csv");
  // A sample: digits, one comma, digits (an ADC value up to 65535).
  const auto is_sample = [](const std::string& line) {
    const std::size_t comma = line.find(',');
    const auto digits = [](std::string_view s) {
      return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
    };
    if (comma == std::string::npos) return false;
    const std::string_view time(line.data(), comma);
    const std::string_view adc(line.data() + comma + 1, line.size() - comma - 1);
    return digits(time) && digits(adc) && adc.size() <= 5 && std::stol(std::string(adc)) <= 65535;
  };
  std::vector<int> corrupted;
  for (std::size_t i = 1; i < lines.size(); ++i)
    if (!is_sample(lines[i])) corrupted.push_back(static_cast<int>(i) + 1);
  ASSERT_EQ(corrupted.size(), 6u);
  const Result r = estimate("corrupted-line.csv");
  EXPECT_EQ(r.log.reading.corrupted.count, 6);
  EXPECT_EQ(r.log.reading.corrupted.first,
            std::vector<int>(corrupted.begin(), corrupted.begin() + 5));
  EXPECT_EQ(r.log.adc.size(), 1501u - 6u);
  const Result clean = estimate("clean.csv");
  EXPECT_NEAR(r.estimate.stats.period_s, clean.estimate.stats.period_s,
              clean.estimate.stats.period_sem_s);
}

TEST(LogCorpus, AMostlyGarbledLogIsALocatedError) {
  const std::string message = error_of("mostly-garbage.csv");
  EXPECT_EQ(message.rfind(kDir + "mostly-garbage.csv:502:", 0), 0u) << message;
  EXPECT_NE(message.find("(33.3 %) are left out, more than the 10 %"), std::string::npos)
      << message;
  EXPECT_NE(message.find("\\x"), std::string::npos) << message;  // garbage shown, escaped
}

TEST(LogCorpus, NoTimeColumnAsksForTheRateAndTheRateWorks) {
  const std::string message = error_of("no-time-column.csv");
  EXPECT_EQ(message.rfind(kDir + "no-time-column.csv:1: error: the header \"sensorValue\" names "
                                 "no time column",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find("--rate"), std::string::npos);
  HallLogOptions rate;
  rate.rate_hz = 500.0;
  EXPECT_EQ(estimate("no-time-column.csv", rate).estimate.stats.period_s,
            estimate("clean.csv").estimate.stats.period_s);
}

TEST(LogCorpus, TheSensorAtTheMiddleOfTheTravelAsksForTheGeometryAndAPairGivesT) {
  const std::string message = error_of("mid-travel.csv");
  EXPECT_EQ(message.rfind(kDir + "mid-travel.csv:", 0), 0u) << message;
  EXPECT_NE(message.find("--geometry pair for one at the middle"), std::string::npos) << message;
  const Result pair = estimate("mid-travel.csv", {}, fl_estimator::kPulsePair);
  EXPECT_NEAR(pair.estimate.stats.period_s, kTrajectoryPeriod, 5e-4 * kTrajectoryPeriod);
  EXPECT_EQ(pair.estimate.stats.periods_discarded, 0u);
}

}  // namespace
}  // namespace fl
