// Reading a whole file: every byte (binary, empty), and an error located at the path, saying
// why, for a file that is missing or a folder.
#include "io/text_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
}  // namespace fl
