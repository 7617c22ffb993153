// Reading a whole file: every byte (binary, empty), and an error located at the path, saying
// why, for a file that is missing or a folder, a device that never ends, or one too large; a pipe
// is read like a file.
#include "io/text_file.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

fs::path folder() {
  const fs::path dir = fs::path(FRICTIONLAB_TEST_BINARY_DIR) / "text-file-test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string error_of(const std::string& path, std::string_view what = "the file") {
  try {
    read_text_file(path, what);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TextFile, ReadsEveryByte) {
  const fs::path dir = folder();
  std::string content("t_us,adc\r\n0,512\n", 17);
  content += '\0';
  content += std::string(200000, 'x');  // longer than one read
  std::ofstream(dir / "a.csv", std::ios::binary) << content;
  EXPECT_EQ(read_text_file((dir / "a.csv").string()), content);
  std::ofstream(dir / "empty.yaml").close();
  EXPECT_EQ(read_text_file((dir / "empty.yaml").string()), "");
}

TEST(TextFile, AFileThatCannotBeReadIsALocatedError) {
  const fs::path dir = folder();
  const std::string missing = (dir / "missing.csv").string();
  EXPECT_EQ(error_of(missing, "the log"),
            missing + ": error: cannot open the log: No such file or directory");
  EXPECT_EQ(error_of(dir.string()), dir.string() + ": error: cannot read the file: Is a directory");
}

TEST(TextFile, ADeviceThatNeverEndsIsRefusedSayingWhatItIs) {
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    const std::string error = error_of(device, "the log");
    EXPECT_EQ(error.rfind(std::string(device) + ": error: expected the log as a file, found a "
                                                "character device",
                          0),
              0u)
        << error;
  }
}

TEST(TextFile, AFileLargerThanTheMostIsRefusedSayingHowLargeItMayBe) {
  const fs::path dir = folder();
  std::ofstream(dir / "big.csv", std::ios::binary) << std::string(3u << 20, 'x');
  try {
    read_text_file((dir / "big.csv").string(), "the log", std::size_t{2} << 20);
    ADD_FAILURE() << "read a file over the limit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the log is larger than 2 MiB"), std::string::npos)
        << e.what();
  }
  std::istringstream stream(std::string(3u << 20, 'x'));
  EXPECT_THROW(read_text_stream(stream, "<stdin>", "the log", std::size_t{2} << 20), InputError);
  std::istringstream small("t_us,adc\n0,512\n");
  EXPECT_EQ(read_text_stream(small, "<stdin>", "the log"), "t_us,adc\n0,512\n");
}

// A line longer than the most a line may have (a file without line ends, a number of megabytes)
// is refused located at its line, counted by "\n", or by "\r" in a text without one.
TEST(TextFile, ALineLongerThanTheMostIsRefusedAtItsLine) {
  const fs::path dir = folder();
  const auto error_with_bound = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    try {
      read_text_file((dir / name).string(), "the log", std::size_t{1} << 20, 100);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string long_line(101, '7');
  const std::string path = (dir / "a.csv").string();
  EXPECT_EQ(
      error_with_bound("a.csv", "t,adc\r\n1,2\r\n" + long_line + "\r\n")
          .rfind(path + ":3: error: line 3 of the log runs past 100 bytes without a line end", 0),
      0u);
  EXPECT_NE(error_with_bound("b.csv", "t,adc\r1,2\r" + long_line)
                .find("b.csv:3: error: line 3 of the log"),
            std::string::npos);
  EXPECT_EQ(error_with_bound("c.csv", "t,adc\n" + std::string(100, '7') + "\n"), "");
  // Without a bound, any line is read.
  std::ofstream(dir / "d.csv", std::ios::binary) << long_line;
  EXPECT_EQ(read_text_file((dir / "d.csv").string()), long_line);
  std::istringstream stream("t,adc\n" + long_line);
  EXPECT_THROW(read_text_stream(stream, "<stdin>", "the log", std::size_t{1} << 20, 100),
               InputError);
}

TEST(TextFile, APipeIsReadLikeAFile) {
  const fs::path dir = folder();
  const std::string fifo = (dir / "log.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << "t_us,adc\n0,512\n"; });
  EXPECT_EQ(read_text_file(fifo, "the log"), "t_us,adc\n0,512\n");
  writer.join();
}

}  // namespace
}  // namespace fl
