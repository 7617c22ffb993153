// Reading the logs people have: a serial monitor's banner and a board's reset garbage before the
// log, a banner that mentions the sensor, byte-order marks and UTF-16 without one, the Serial
// Plotter's label:value lines, the Arduino IDE's timestamps, Arduino-style headers, no header, no
// time column, decimal commas, corrupted lines and times out of order (left out, counted, located;
// refused beyond 10 %), and a board that restarted in the middle.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/field_spelling.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/hall_log_reader.hpp"
#include "io/input_error.hpp"

namespace fl {
namespace {

// `n` lines "t,v" from t0 in steps of dt, values 512 + i % 7.
std::string lines(int n, double t0 = 0.0, double dt = 1000.0, char sep = ',') {
  std::string out;
  for (int i = 0; i < n; ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f%c%d\n", t0 + i * dt, sep, 512 + i % 7);
    out += buf;
  }
  return out;
}

std::string error_of(const std::string& text, const HallLogOptions& options = {}) {
  try {
    parse_hall_log(text, "log.csv", options);
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

void expect_starts(const std::string& message, const std::string& start) {
  EXPECT_EQ(message.rfind(start, 0), 0u) << "message: " << message << "\nexpected: " << start;
}

TEST(HallLogReader, SkipsABannerAndResetGarbageBeforeTheLogAndCountsThem) {
  const std::string text = std::string(
                               "Monitor port settings:\n"
                               "  baudrate=250000\n"
                               "Connecting to /dev/ttyACM0. Press CTRL-C to exit.\n") +
                           std::string(
                               "\xF0\x8C\x00\xFF"
                               "12\xE0\n",
                               8) +
                           "# frictionlab rig firmware 1: sample_hz=1000\n"
                           "t_us,adc\n" +
                           lines(100);
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.lines_skipped, 4);
  EXPECT_EQ(log.reading.header_line, 6);
  EXPECT_EQ(log.reading.format, "firmware");
  ASSERT_EQ(log.adc.size(), 100u);
  EXPECT_EQ(log.line.front(), 7);
  EXPECT_DOUBLE_EQ(log.t_s[99], 0.099);
  EXPECT_EQ(log.reading.corrupted.count, 0);
}

TEST(HallLogReader, ByteOrderMarksAndUtf16) {
  const std::string plain = "t_ms,adc\n" + lines(50, 0, 1);
  const HallLog utf8 = parse_hall_log("\xEF\xBB\xBF" + plain, "x");
  EXPECT_EQ(utf8.encoding, "utf-8 with BOM");
  EXPECT_EQ(utf8.reading.time_column, "t_ms");
  std::string utf16 = "\xFF\xFE";
  for (char c : plain) {
    utf16 += c;
    utf16 += '\0';
  }
  const HallLog wide = parse_hall_log(utf16, "x");
  EXPECT_EQ(wide.encoding, "utf-16le");
  EXPECT_EQ(wide.adc, utf8.adc);
  EXPECT_EQ(wide.t_s, utf8.t_s);
}

TEST(HallLogReader, Utf16WithoutAByteOrderMark) {
  const std::string plain = "t_ms,adc\n" + lines(50, 0, 1);
  std::string little;
  std::string big;
  for (char c : plain) {
    little += std::string{c, '\0'};
    big += std::string{'\0', c};
  }
  const HallLog utf8 = parse_hall_log(plain, "x");
  const HallLog le = parse_hall_log(little, "x");
  EXPECT_EQ(le.encoding, "utf-16le (no BOM)");
  EXPECT_EQ(le.adc, utf8.adc);
  EXPECT_EQ(le.t_s, utf8.t_s);
  const HallLog be = parse_hall_log(big, "x");
  EXPECT_EQ(be.encoding, "utf-16be (no BOM)");
  EXPECT_EQ(be.adc, utf8.adc);
}

// A banner that mentions the sensor reads like a header naming no time: it is a banner when the
// real header, or samples of another shape, follow it; the header of a log of values only when
// lines of its own shape follow (and then its message, with its advice, is the log's).
TEST(HallLogReader, ABannerThatMentionsTheSensorIsNotTakenForTheHeader) {
  for (const std::string banner :
       {"Hall rig ready", "Hall sensor test", "hall effect logger v1.0", "Hall sensor: ready"}) {
    const HallLog with_header = parse_hall_log(banner + "\nt_ms,hall\n" + lines(100, 0, 1), "x");
    EXPECT_EQ(with_header.reading.header_line, 2) << banner;
    EXPECT_EQ(with_header.reading.lines_skipped, 1) << banner;
    EXPECT_EQ(with_header.reading.time_unit, "ms") << banner;
    ASSERT_EQ(with_header.adc.size(), 100u) << banner;
    const HallLog without = parse_hall_log(banner + "\n" + lines(100, 0, 1), "x");
    EXPECT_EQ(without.reading.columns_from, "position") << banner;
    EXPECT_EQ(without.adc.size(), 100u) << banner;
  }
  // A real one-column header over values: the header's message, and --rate reads it.
  std::string values = "hall\n";
  for (int i = 0; i < 100; ++i) values += std::to_string(512 + i % 7) + "\n";
  expect_starts(error_of(values), "log.csv:1: error: the header \"hall\" names no time column");
  HallLogOptions rate;
  rate.rate_hz = 1000.0;
  EXPECT_EQ(parse_hall_log(values, "x", rate).adc.size(), 100u);
}

TEST(HallLogReader, TheSerialPlottersLabelValueLines) {
  std::string text = "Hall sensor test\n";
  for (int i = 0; i < 100; ++i)
    text += "t:" + std::to_string(i) + "\tHall:" + std::to_string(512 + i % 7) + "\r\n";
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.format, "serial-plotter");
  EXPECT_EQ(log.reading.time_column, "t");
  EXPECT_EQ(log.reading.adc_column, "Hall");
  EXPECT_EQ(log.reading.time_unit, "ms");  // inferred: a sample a millisecond
  ASSERT_EQ(log.adc.size(), 100u);
  EXPECT_EQ(log.adc[8], 513);
  EXPECT_DOUBLE_EQ(log.t_s[99], 0.099);
  // Commas or spaces between the pairs, as the IDE also takes them; a line of other labels is
  // a corrupted line of this log.
  std::string spaced;
  for (int i = 0; i < 100; ++i)
    spaced += "t:" + std::to_string(i) + (i % 2 ? ", " : " ") + "Hall:512\n";
  spaced += "x:1 y:2\n";
  for (int i = 100; i < 110; ++i) spaced += "t:" + std::to_string(i) + ",Hall:512\n";
  const HallLog mixed = parse_hall_log(spaced, "x");
  EXPECT_EQ(mixed.adc.size(), 110u);
  EXPECT_EQ(mixed.reading.corrupted.count, 1);
  EXPECT_EQ(mixed.reading.corrupted.first.front(), 101);
}

TEST(HallLogReader, TheArduinoIdesTimestampsAreTakenOff) {
  std::string text = "10:41:07.019 -> t_us,adc\r\n";
  for (int i = 0; i < 20; ++i)
    text += "10:41:07." + std::to_string(100 + i) + " -> " + std::to_string(i * 1000) + "," +
            std::to_string(500 + i) + "\r\n";
  text += "10:41:08.000 -> 20000,5x0\r\n";  // located past the prefix
  for (int i = 21; i < 40; ++i)
    text += "10:41:08." + std::to_string(100 + i) + " -> " + std::to_string(i * 1000) + ",520\r\n";
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_TRUE(log.reading.ide_timestamps);
  ASSERT_EQ(log.adc.size(), 39u);
  EXPECT_EQ(log.adc[19], 519);
  EXPECT_DOUBLE_EQ(log.t_s[20], 0.021);
  EXPECT_EQ(log.reading.corrupted.count, 1);
  EXPECT_EQ(log.reading.corrupted.first, std::vector<int>{22});
}

TEST(HallLogReader, LinesEndingInCarriageReturnsAlone) {
  std::string text = "t_us,adc\r" + lines(30);
  for (char& c : text)
    if (c == '\n') c = '\r';
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.adc.size(), 30u);
}

TEST(HallLogReader, DecimalCommasWhereTheDelimiterIsNotAComma) {
  const HallLog semi =
      parse_hall_log("time (s);ADC Value\n0,000;512\n0,001;513,0\n0,002;514\n", "x");
  EXPECT_TRUE(semi.reading.decimal_comma);
  EXPECT_EQ(semi.reading.adc_column, "ADC Value");
  EXPECT_EQ(semi.reading.time_unit, "s");
  ASSERT_EQ(semi.t_s.size(), 3u);
  EXPECT_DOUBLE_EQ(semi.t_s[2], 0.002);
  EXPECT_EQ(semi.adc[1], 513);
  const HallLog tab = parse_hall_log("time_s\tvalue\n0,5\t512\n0,501\t513\n", "x");
  EXPECT_DOUBLE_EQ(tab.t_s[1], 0.501);
  // With commas between the fields a comma is never a decimal one: "0,5,512" has three fields.
  const HallLog comma = parse_hall_log("t_ms,adc,x\n0,5,512\n1,6,513\n", "x");
  EXPECT_FALSE(comma.reading.decimal_comma);
  EXPECT_EQ(comma.adc[1], 6);
}

TEST(HallLogReader, ArduinoStyleHeaders) {
  struct Case {
    std::string header;
    const char* time;
    const char* value;
    const char* unit;
  };
  for (const Case& c : {
           Case{"millis(),analogRead(A0)", "millis()", "analogRead(A0)", "ms"},
           Case{"micros,sensorValue", "micros", "sensorValue", "us"},
           Case{"Time [ms]\tADC Value", "Time [ms]", "ADC Value", "ms"},
           Case{"timestamp;Hall", "timestamp", "Hall", "ms"},  // no unit: 1 kHz in ms
           Case{"elapsed_ms sensor", "elapsed_ms", "sensor", "ms"},
       }) {
    const char sep = c.header.find(';') != std::string::npos    ? ';'
                     : c.header.find('\t') != std::string::npos ? '\t'
                     : c.header.find(',') != std::string::npos  ? ','
                                                                : ' ';
    const HallLog log = parse_hall_log(c.header + "\n" + lines(80, 0, 1, sep), "x");
    EXPECT_EQ(log.reading.time_column, c.time) << c.header;
    EXPECT_EQ(log.reading.adc_column, c.value) << c.header;
    EXPECT_EQ(log.reading.time_unit, c.unit) << c.header;
    EXPECT_EQ(log.adc.size(), 80u) << c.header;
  }
}

TEST(HallLogReader, NoHeaderReadsByPositionAndInfersTheUnit) {
  const HallLog ms = parse_hall_log(lines(200, 5, 1), "x");
  EXPECT_EQ(ms.reading.columns_from, "position");
  EXPECT_EQ(ms.reading.time_unit, "ms");
  EXPECT_EQ(ms.reading.time_unit_from, "inferred");
  EXPECT_DOUBLE_EQ(ms.t_s[1] - ms.t_s[0], 0.001);
  const HallLog us = parse_hall_log(lines(200, 0, 500), "x");
  EXPECT_EQ(us.reading.time_unit, "us");
  EXPECT_NEAR(us.t_s[199], 0.0995, 1e-12);
  // The time is the field that increases.
  const HallLog swapped = parse_hall_log("512,0\n530,1\n520,2\n515,3\n", "x");
  EXPECT_EQ(swapped.reading.time_column, "field 2");
  EXPECT_EQ(swapped.adc[1], 530);
  // --time-unit says otherwise than the inference.
  HallLogOptions seconds;
  seconds.time_unit = "s";
  EXPECT_DOUBLE_EQ(parse_hall_log(lines(10, 0, 1), "x", seconds).t_s[3], 3.0);
}

TEST(HallLogReader, ColumnsAndRateFromTheCommandLine) {
  HallLogOptions columns;
  columns.columns = "adc,_,t_ms";
  const HallLog by_option =
      parse_hall_log("t,whatever,adc\n512,9,0\n513,9,2\n514,9,4\n", "x", columns);
  EXPECT_EQ(by_option.reading.columns_from, "columns");
  EXPECT_EQ(by_option.reading.lines_skipped, 1);  // the header it replaces
  EXPECT_DOUBLE_EQ(by_option.t_s[2], 0.004);
  EXPECT_EQ(by_option.adc[2], 514);

  HallLogOptions rate;
  rate.rate_hz = 500.0;
  std::string values_text = "512\n513\n514\nx\n";
  for (int i = 0; i < 20; ++i) values_text += "516\n";
  const HallLog values = parse_hall_log(values_text, "x", rate);
  EXPECT_EQ(values.reading.time_unit_from, "rate");
  ASSERT_EQ(values.adc.size(), 23u);
  EXPECT_DOUBLE_EQ(values.t_s[3], 0.008);  // the garbled line still took a sample's time
  // --rate times a log that has a time column too.
  const HallLog timed = parse_hall_log("t_ms,adc\n0,512\n0,513\n0,514\n", "x", rate);
  EXPECT_DOUBLE_EQ(timed.t_s[2], 0.004);
  EXPECT_EQ(timed.reading.repeated_times.count, 0);

  for (const char* bad : {"t,t_ms,adc", "t_us", "adc,banana", "adc,value"}) {
    HallLogOptions o;
    o.columns = bad;
    expect_starts(error_of("1,2,3\n", o), "--columns: error: expected");
  }
  HallLogOptions unit;
  unit.time_unit = "minutes";
  expect_starts(error_of("t,adc\n", unit), "--time-unit: error: expected us, ms or s");
}

TEST(HallLogReader, ACorruptedLineIsLeftOutCountedAndLocated) {
  std::string text = "t_us,adc\n" + lines(20) +
                     "21000,5\xFF"
                     "12\n" +
                     "220" + "\n" + lines(20, 23000) + "43000\n" + lines(60, 44000);
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.corrupted.count, 3);
  EXPECT_EQ(log.reading.corrupted.first, (std::vector<int>{22, 23, 44}));
  EXPECT_EQ(log.adc.size(), 100u);
  EXPECT_EQ(log.reading.data_lines, 103);
}

TEST(HallLogReader, RepeatedAndOutOfOrderTimesAreLeftOutCountedAndLocated) {
  std::string text = "t_ms,adc\n" + lines(50, 0, 1);
  text += "49,600\n";    // line 52: millis() read twice in one millisecond
  text += "4,601\n";     // line 53: back in time
  text += "5000,602\n";  // line 54: jumped ahead of the next one
  text += lines(50, 50, 1);
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.repeated_times.first, std::vector<int>{52});
  EXPECT_EQ(log.reading.out_of_order.first, (std::vector<int>{53, 54}));
  ASSERT_EQ(log.adc.size(), 100u);
  for (std::size_t i = 1; i < log.t_s.size(); ++i)
    EXPECT_NEAR(log.t_s[i] - log.t_s[i - 1], 0.001, 1e-12) << i;
}

TEST(HallLogReader, OnlyTheFirstFewLinesOfAKindAreListed) {
  std::string text = "t_us,adc\n";
  for (int i = 0; i < 100; ++i) text += (i % 20 == 7 ? "garbage\n" : lines(1, i * 1000.0));
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.corrupted.count, 5);
  EXPECT_EQ(log.reading.corrupted.first.size(), 5u);
  EXPECT_EQ(log.reading.corrupted.first.back(), 2 + 87);
}

TEST(HallLogReader, MoreThanTenPercentLeftOutIsALocatedErrorWithAWayOut) {
  // millis() printed at 2 kHz: every other time repeats.
  std::string text = "millis,adc\n";
  for (int i = 0; i < 400; ++i)
    text += std::to_string(i / 2) + "," + std::to_string(512 + i % 5) + "\n";
  const std::string message = error_of(text);
  expect_starts(message,
                "log.csv:3:1: error: time 0 ms repeats the previous sample's (line 2); 200 "
                "of the 400 lines after the header (50 %) are left out");
  // The rate advised is the log's own: its lines from the first time to the last over that span.
  EXPECT_NE(message.find("(for example --rate 2000Hz)"), std::string::npos) << message;
  // ... and the way out works.
  HallLogOptions rate;
  rate.rate_hz = 2000.0;
  const HallLog log = parse_hall_log(text, "x", rate);
  EXPECT_EQ(log.adc.size(), 400u);
  EXPECT_DOUBLE_EQ(log.t_s[399], 399 / 2000.0);

  std::string garbled = "t_us,adc\n";
  for (int i = 0; i < 100; ++i)
    garbled += i % 4 == 3 ? "\xE0\xFE"
                            "1\x80\n"
                          : lines(1, i * 1000.0);
  expect_starts(error_of(garbled), "log.csv:5: error: expected at least 2 fields");
  EXPECT_NE(error_of(garbled).find("25 of the 100 lines after the header (25 %)"),
            std::string::npos)
      << error_of(garbled);
  // Exactly 10 % is still read.
  std::string tenth = "t_us,adc\n";
  for (int i = 0; i < 100; ++i) tenth += i % 10 == 3 ? "x\n" : lines(1, i * 1000.0);
  EXPECT_EQ(parse_hall_log(tenth, "x").reading.corrupted.count, 10);
}

TEST(HallLogReader, ABoardThatRestartedStartsANewRunAndTheLongestIsUsed) {
  const std::string banner = "# frictionlab rig firmware 1: sample_hz=1000\nt_us,adc\n";
  const std::string text = banner + lines(30) + "3000" + banner + lines(80) + banner + lines(10);
  const HallLog log = parse_hall_log(text, "x");
  EXPECT_EQ(log.reading.segments, 3);
  EXPECT_EQ(log.segment, 1);
  EXPECT_EQ(log.adc.size(), 80u);
  EXPECT_EQ(log.segment_samples_left_out, 40);
  EXPECT_EQ(log.line.front(), 2 + 30 + 3);
  EXPECT_EQ(log.reading.out_of_order.count + log.reading.corrupted.count, 0);
  // A header line again, without the firmware's banner, does the same.
  const HallLog twice = parse_hall_log("t_us,adc\n" + lines(20) + "t_us,adc\n" + lines(50), "x");
  EXPECT_EQ(twice.reading.segments, 2);
  EXPECT_EQ(twice.adc.size(), 50u);
}

TEST(HallLogReader, SamplesArriveAsTheLinesDo) {
  HallLogReader reader("port", {});
  reader.add_line("t_us,adc", 1);
  std::size_t got = 0;
  for (int i = 0; i < 10; ++i) {
    reader.add_line(std::to_string(i * 1000) + ",512", i + 2);
    got += reader.take().size();
  }
  EXPECT_EQ(got, 9u);  // the last waits for the next to confirm its time
  // A time without a unit is held until the unit is known (64 samples).
  HallLogReader unitless("port", {});
  unitless.add_line("time,adc", 1);
  got = 0;
  for (int i = 0; i < 70; ++i) {
    unitless.add_line(std::to_string(i) + ",512", i + 2);
    const std::size_t n = unitless.take().size();
    if (i < 64) {
      EXPECT_EQ(n, 0u) << i;
    }
    got += n;
  }
  EXPECT_EQ(got, 69u);
  EXPECT_EQ(unitless.reading().time_unit, "ms");
}

}  // namespace
}  // namespace fl
