// trim: blanks (or the characters asked for) off both ends, nothing from the middle.
#include "text/text.hpp"

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

// Only A to Z change: digits, punctuation and the bytes of UTF-8 (the caption's "\xce\xbc", mu)
// stay as they are.
TEST(AsciiLower, LowersAToZAndNothingElse) {
  EXPECT_EQ(ascii_lower("ADC Value (A0) T_us"), "adc value (a0) t_us");
  EXPECT_EQ(ascii_lower("\xce\x9c\xce\xbc Z@[`{"), "\xce\x9c\xce\xbc z@[`{");
  EXPECT_EQ(ascii_lower(""), "");
}

}  // namespace
}  // namespace fl
