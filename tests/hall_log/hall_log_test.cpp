// Reading Hall-sensor logs: the rig firmware's serial output and CSVs of time and ADC value, with
// the columns found by name, and located errors for logs that cannot be used.
#include "hall_log/hall_log.hpp"
#include "cli/field_spelling.hpp"

#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace fl {
namespace {

// The message parse_hall_log throws for `text` ("" when it throws none).
std::string error_of(const std::string& text) {
  try {
    parse_hall_log(text, "log.csv");
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

TEST(HallLog, TheFirmwaresSerialOutput) {
  const std::string text =
      "# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 raw_every=1\r\n"
      "t_us,adc\r\n"
      "0,512\r\n"
      "1000,513\r\n"
      "# signal learned: baseline=512.3 polarity=+1 timing_level=611.0\r\n"
      "2000,600\r\n"
      "# period i=0 end_us=1500 T_us=790000.0 accepted\r\n"
      "# stats periods=1 N=1 discarded=0 T_mean_us=790000.0 dT_us=0.0\r\n"
      "3000,514\r\n";
  const HallLog log = parse_hall_log(text, "rig.log");
  EXPECT_EQ(log.reading.format, "firmware");
  EXPECT_EQ(log.reading.time_column, "t_us");
  EXPECT_EQ(log.reading.adc_column, "adc");
  EXPECT_EQ(log.reading.time_unit, "us");
  EXPECT_EQ(log.reading.header_line, 2);
  EXPECT_EQ(log.reading.comment_lines, 4);
  EXPECT_EQ(log.reading.lines_skipped, 0);
  ASSERT_EQ(log.adc.size(), 4u);
  EXPECT_EQ(log.adc[2], 600);
  EXPECT_EQ(log.line[2], 6);
  EXPECT_DOUBLE_EQ(log.t_s[3], 0.003);
  EXPECT_EQ(log.t_us[3], 3000u);
}

TEST(HallLog, ColumnsAreFoundByNameInAnyOrderAndUnit) {
  struct Case {
    const char* text;
    const char* time;
    const char* adc;
    double t1_s;  // the second sample's time
  };
  for (const Case& c : {
           Case{"t_s,adc\n0.5,512\n0.501,513\n", "t_s", "adc", 0.501},
           // No unit in the name: the one that makes the rate 20 Hz to 20 kHz (here 1 kHz in s).
           Case{"time,value\n10,512\n10.001,513\n", "time", "value", 10.001},
           Case{"adc,t_us\n512,100\n513,1100\n", "t_us", "adc", 0.0011},
           Case{"Time (ms);Hall\n0;512\n2.5;513\n", "Time (ms)", "Hall", 0.0025},
           Case{"x\ttimestamp_us\tA0\n7\t5\t512\n7\t15\t513\n", "timestamp_us", "A0", 15e-6},
           Case{"millis reading\n0 512\n4 513\n", "millis", "reading", 0.004},
           Case{"\"t_ms\",\"adc\",\"x_mm\"\n0,512,1\n1,513,2\n", "t_ms", "adc", 0.001},
       }) {
    const HallLog log = parse_hall_log(c.text, "log.csv");
    EXPECT_EQ(log.reading.format, "csv") << c.text;
    EXPECT_EQ(log.reading.time_column, c.time) << c.text;
    EXPECT_EQ(log.reading.adc_column, c.adc) << c.text;
    ASSERT_EQ(log.adc.size(), 2u) << c.text;
    EXPECT_EQ(log.adc[1], 513) << c.text;
    EXPECT_NEAR(log.t_s[1], c.t1_s, 1e-12) << c.text;
    EXPECT_EQ(log.t_us[0], 0u) << c.text;  // the estimator's clock starts at the first sample
  }
}

TEST(HallLog, TheFirmwaresMicrosecondClockWrapsAround) {
  const HallLog log = parse_hall_log("t_us,adc\n4294966296,512\n4294967000,513\n1000,514\n", "x");
  EXPECT_EQ(log.reading.clock_wraps, 1);
  ASSERT_EQ(log.t_s.size(), 3u);
  EXPECT_NEAR(log.t_s[2] - log.t_s[0], 0.002, 1e-12);
  EXPECT_EQ(log.t_us[2], 2000u);
}

TEST(HallLog, ErrorsNameTheLineAndSayWhatWasFound) {
  struct Case {
    const char* text;
    const char* message;
  };
  for (const Case& c : {
           Case{"", "log.csv:1: error: the log is empty: expected a header naming the time"},
           Case{"# only\n# comments\n", "log.csv:1: error: the log has only comment lines"},
           Case{"Monitor port settings:\n  baudrate=250000\n",
                "log.csv:1: error: none of the log's 2 lines is a header or a sample: expected a "
                "header naming the time and ADC columns"},
           Case{"1,2,3\n4,5,6\n7,8,9\n",
                "log.csv:1: error: 3 numbers per line and no header; say which field is the time "
                "and which the ADC value with --columns"},
           Case{"512\n513\n514\n",
                "log.csv:1: error: one number per line and no header: ADC values without times; "
                "give the sample rate with --rate"},
           Case{"sensorValue\n512\n",
                "log.csv:1: error: the header \"sensorValue\" names no time "
                "column"},
           Case{"x,adc\n0,512\n", "log.csv:1: error: the header \"x,adc\" names no time column"},
           Case{"t_us,temperature\n0,20\n",
                "log.csv:1: error: the header \"t_us,temperature\" names no ADC column"},
           Case{"t_us,adc\n", "log.csv:1: error: no samples after the header"},
           Case{"t_us,adc\n0,512\n1000,5l2\n",
                "log.csv:3:6: error: column \"adc\": expected a number, found \"5l2\""},
           Case{"t_us,adc\n0,512\nabc,513\n",
                "log.csv:3:1: error: column \"t_us\": expected a number, found \"abc\""},
           // One of three out of order is more than the 10 % the reader leaves out.
           Case{"t_s,adc\n0.1,512\n0.3,513\n0.2,514\n",
                "log.csv:3:1: error: time 0.3 s is ahead of the next sample's 0.2 s (line 4): "
                "the times must increase; 1 of the 3 lines after the header (33.3 %) are left "
                "out"},
           Case{"t_s,adc\n0.1,512\n0.2,513\n0.05,514\n",
                "log.csv:4:1: error: time 0.05 s is not after the previous sample's 0.2 s (line "
                "3): the times must increase"},
           Case{"t_us,adc\n0,512\n0,513\n",
                "log.csv:3:1: error: time 0 us repeats the previous sample's (line 2); 1 of the 2 "
                "lines after the header (50 %) are left out, more than the 10 % the reader skips: "
                "1 repeat the time before them"},
           Case{"time,value\n0,512\n100000,513\n200000,514\n",
                "log.csv:2: error: the time column \"time\" names no unit, and its step of 100000 "
                "per sample fits none"},
           Case{"t_us,adc\n0,512\n1000\n", "log.csv:3: error: expected at least 2 fields"},
           Case{"t_us,adc\n0,-4\n",
                "log.csv:2:3: error: column \"adc\": expected an ADC value from 0 to 65535 "
                "counts, found -4"},
           Case{"t_us,adc\n0,nan\n", "log.csv:2:3: error: column \"adc\": expected a number"},
       }) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.rfind(c.message, 0), 0u) << "log:\n" << c.text << "\nmessage: " << message;
  }
}

TEST(HallLog, ACaptureStoppedMidLineLeavesTheUnfinishedLineOut) {
  const HallLog cut = parse_hall_log("t_us,adc\n0,512\n1000,513\n20", "x");
  EXPECT_TRUE(cut.reading.unfinished_last_line);
  EXPECT_EQ(cut.adc.size(), 2u);
  const HallLog whole = parse_hall_log("t_us,adc\n0,512\n1000,513\n2000,514", "x");
  EXPECT_FALSE(whole.reading.unfinished_last_line);
  EXPECT_EQ(whole.adc.size(), 3u);
}

TEST(HallLog, AFileThatCannotBeOpened) {
  try {
    read_hall_log("/nonexistent/hall.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/hall.csv: error: cannot open the log", 0),
              0u)
        << e.what();
  }
}

}  // namespace
}  // namespace fl
