// One UTF-8 character at a time: code points and lengths of each width, and every way bytes fail
// to be a character.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "text/utf8.hpp"

namespace fl {
namespace {

TEST(Utf8, ReadsEachWidthWithItsLength) {
  const std::string_view text = "a\xc2\xb1\xe2\x82\x96\xf0\x9f\x99\x82";  // a ± ₖ 🙂
  const auto a = utf8_character_at(text, 0);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->code, U'a');
  EXPECT_EQ(a->bytes, 1u);
  EXPECT_EQ(utf8_character_at(text, 1)->code, U'\u00b1');
  EXPECT_EQ(utf8_character_at(text, 1)->bytes, 2u);
  EXPECT_EQ(utf8_character_at(text, 3)->code, U'\u2096');
  EXPECT_EQ(utf8_character_at(text, 3)->bytes, 3u);
  EXPECT_EQ(utf8_character_at(text, 6)->code, U'\U0001F642');
  EXPECT_EQ(utf8_character_at(text, 6)->bytes, 4u);
  EXPECT_FALSE(utf8_character_at(text, 10));  // past the end
}

TEST(Utf8, WhatIsNotACharacterIsNothing) {
  EXPECT_FALSE(utf8_character_at("\xb1", 0));      // a stray continuation byte
  EXPECT_FALSE(utf8_character_at("\xe2\x82", 0));  // cut short
  EXPECT_FALSE(
      utf8_character_at("\xe2"
                        "a"
                        "\x96",
                        0));                               // not continued
  EXPECT_FALSE(utf8_character_at("\xc0\xaf", 0));          // "/" overlong
  EXPECT_FALSE(utf8_character_at("\xed\xa0\x80", 0));      // a surrogate, U+D800
  EXPECT_FALSE(utf8_character_at("\xf4\x90\x80\x80", 0));  // beyond U+10FFFF
  EXPECT_FALSE(utf8_character_at("\xff", 0));
}

// A file name that is not UTF-8, for a message or a JSON string: each byte that is not part of a
// character as \xNN, every character kept.
TEST(Utf8, BytesThatAreNoCharacterAreEscaped) {
  EXPECT_EQ(escape_invalid_utf8("bad\xff.csv"), "bad\\xff.csv");
  EXPECT_EQ(escape_invalid_utf8("a\xc2\xb1 \xe2\x82\x96"), "a\xc2\xb1 \xe2\x82\x96");  // kept
  EXPECT_EQ(escape_invalid_utf8("\xe2\x82"), "\\xe2\\x82");                            // cut short
  EXPECT_EQ(escape_invalid_utf8("\xc0\xaf/"), "\\xc0\\xaf/");                          // overlong
  EXPECT_EQ(escape_invalid_utf8("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(escape_invalid_utf8(""), "");
  const std::string once = escape_invalid_utf8("x\x80y\xfe");
  EXPECT_EQ(once, "x\\x80y\\xfe");
  EXPECT_EQ(escape_invalid_utf8(once), once);  // the escaped text is UTF-8
}

}  // namespace
}  // namespace fl
