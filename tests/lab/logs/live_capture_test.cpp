// A live capture (lab/logs/live_capture.hpp) against the log reader on the same bytes as a file:
// whatever pieces the port hands them in, the same samples of the run being received; a board
// that restarts begins a new run; a line that never ends is taken at the line limit, so the
// capture holds no more than that; a full raw log stops it; lines that are no log are handed on
// after the refusal.
#include "lab/logs/live_capture.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_command.hpp"

namespace fl {
namespace {

const std::string kLogs = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/data/logs/";

// The bytes handed to a capture `piece` bytes at a time; the samples it kept, the lines handed on.
struct Captured {
  std::vector<LogSample> samples;
  std::string lines;
  int runs_begun = 0;
};
Captured capture_in_pieces(const std::string& bytes, std::size_t piece) {
  LiveCapture capture("port", HallLogOptions{});
  Captured out;
  const auto on_line = [&](std::string_view line) {
    out.lines.append(line);
    return true;
  };
  const auto on_sample = [&](const LogSample&, bool new_run) { out.runs_begun += new_run; };
  for (std::size_t at = 0; at < bytes.size(); at += piece)
    EXPECT_TRUE(capture.add(std::string_view(bytes).substr(at, piece), false, on_line, on_sample));
  capture.add("", true, on_line, on_sample);
  capture.finish(on_sample);
  out.samples = capture.samples();
  return out;
}

TEST(LiveCapture, AnyPiecesGiveTheFilesSamplesOfTheRunBeingReceived) {
  const std::string bytes = test::read_text(kLogs + "board-restarted.csv");
  const HallLog file = read_hall_log(kLogs + "board-restarted.csv");
  ASSERT_GE(file.reading.segments, 2);
  for (std::size_t piece : {1u, 7u, 100u, 4096u, 1u << 20}) {
    const Captured c = capture_in_pieces(bytes, piece);
    // Every byte handed on as received, the board's restart a new run, its samples those of the
    // last run of the file.
    EXPECT_EQ(c.lines, bytes) << piece;
    EXPECT_EQ(c.runs_begun, file.reading.segments - 1) << piece;
    ASSERT_FALSE(c.samples.empty());
    EXPECT_EQ(c.samples.back().adc, file.adc.back()) << piece;
    EXPECT_EQ(c.samples.back().line, file.line.back()) << piece;
  }
}

TEST(LiveCapture, ALineThatNeverEndsIsTakenAtTheLineLimit) {
  LiveCapture capture("port", HallLogOptions{});
  std::size_t longest = 0;
  const auto on_line = [&](std::string_view line) {
    longest = std::max(longest, line.size());
    return true;
  };
  // 10 MB of bytes without a newline, as a wrong baud rate gives them, a kilobyte at a time.
  const std::string kilobyte(1024, '\x9c');
  for (int i = 0; i < 10 * 1024; ++i) capture.add(kilobyte, false, on_line, {});
  EXPECT_LE(longest, kMostLogLineBytes + kilobyte.size());
  EXPECT_GE(capture.lines(), 10 * 1024 * 1024 / static_cast<int>(kMostLogLineBytes + 1024));
}

TEST(LiveCapture, AFullRawLogStopsIt) {
  LiveCapture capture("port", HallLogOptions{});
  int taken = 0;
  const auto on_line = [&](std::string_view) { return ++taken <= 3; };
  EXPECT_FALSE(capture.add("t_us,adc\n0,500\n1000,500\n2000,500\n3000,500\n", false, on_line, {}));
  EXPECT_EQ(capture.lines(), 3);
}

TEST(LiveCapture, LinesThatAreNoLogAreRefusedOnceAndStillHandedOn) {
  LiveCapture capture("port", HallLogOptions{});
  std::string lines, why;
  const auto on_line = [&](std::string_view line) {
    lines.append(line);
    return true;
  };
  // ADC values without times, and no rate given: the reader cannot read them as a log.
  std::string text;
  for (int i = 0; i < 40; ++i) text += std::to_string(500 + i % 3) + "\n";
  EXPECT_TRUE(capture.add(text, false, on_line, {}, [&](const InputError& e) {
    EXPECT_TRUE(why.empty());
    why = e.what();
  }));
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(lines, text);
  // Without a place for the refusal, it is thrown.
  LiveCapture strict("port", HallLogOptions{});
  EXPECT_THROW(strict.add(text, false, {}, {}), InputError);
}

}  // namespace
}  // namespace fl
