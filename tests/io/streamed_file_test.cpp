// A file written in pieces is seen only whole: nothing at its path until commit(), the old file
// kept until then, nothing left behind by a file never committed, and a restart forgets what came.
#include "io/streamed_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include "assets/temp_dir.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

// Writes `lines` numbered lines through `file`, a piece per line.
std::string write_lines(StreamedFile& file, int lines) {
  std::string expected;
  for (int i = 0; i < lines; ++i) {
    const std::string line = std::to_string(i) + ",a line of some length to fill the pieces\n";
    file.pending() += line;
    file.wrote();
    expected += line;
  }
  return expected;
}

std::size_t entries(const fs::path& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), {}));
}

TEST(StreamedFile, AFileLargerThanItsPiecesIsWholeOnlyOnceCommitted) {
  test::TempDir dir;
  const fs::path path = dir.path() / "trajectory.csv";
  std::ofstream(path) << "the old file\n";
  StreamedFile file(path.string());
  // Several pieces of 256 KiB reach the disk before the commit.
  const std::string expected = write_lines(file, 40000);
  ASSERT_GT(expected.size(), 1u << 20);
  EXPECT_EQ(test::read_text(path), "the old file\n");
  file.commit();
  EXPECT_EQ(test::read_text(path), expected);
  EXPECT_EQ(entries(dir.path()), 1u);  // no temporary file left
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::others_read, fs::perms::others_read);
}

TEST(StreamedFile, AFileNeverCommittedLeavesNothingAndTheOldFileAsItWas) {
  test::TempDir dir;
  const fs::path path = dir.path() / "hall.csv";
  std::ofstream(path) << "t_us,adc\n0,512\n";
  {
    StreamedFile file(path.string());
    write_lines(file, 40000);
  }
  EXPECT_EQ(test::read_text(path), "t_us,adc\n0,512\n");
  EXPECT_EQ(entries(dir.path()), 1u);
  {
    StreamedFile fresh((dir.path() / "new.csv").string());
    write_lines(fresh, 10);
  }
  EXPECT_FALSE(fs::exists(dir.path() / "new.csv"));
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(StreamedFile, ARestartForgetsWhatWasWritten) {
  test::TempDir dir;
  const fs::path path = dir.path() / "trajectory.csv";
  StreamedFile file(path.string());
  write_lines(file, 40000);
  file.restart();
  const std::string expected = write_lines(file, 7);
  file.commit();
  EXPECT_EQ(test::read_text(path), expected);
}

TEST(StreamedFile, AFolderThatCannotHoldItIsNamed) {
  test::TempDir dir;
  std::ofstream(dir.path() / "a-file") << "x";
  try {
    StreamedFile file((dir.path() / "a-file" / "trajectory.csv").string());
    FAIL() << "a file inside a file was created";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("a-file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl
