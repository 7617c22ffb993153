// trim: blanks (or the characters asked for) off both ends, nothing from the middle.
#include "core/text.hpp"

#include <gtest/gtest.h>

namespace fl {
namespace {

TEST(Trim, StripsBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  89 mm\t\r\n"), "89 mm");
  EXPECT_EQ(trim("mm"), "mm");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim(" \t \r\n"), "");
  EXPECT_EQ(trim("a  b"), "a  b");
}

TEST(Trim, StripsTheCharactersAskedFor) {
  EXPECT_EQ(trim(" \"t_us\" ", " \t\"'"), "t_us");
  EXPECT_EQ(trim("'adc'", " '"), "adc");
  EXPECT_EQ(trim("\"\"", "\""), "");
}

}  // namespace
}  // namespace fl
