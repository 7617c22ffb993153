// Base64 decoding against RFC 4648's test vectors (section 10), every byte value, and what is
// not base64.
#include "text/base64.hpp"

#include <string>

#include <gtest/gtest.h>

namespace fl {
namespace {

TEST(Base64, DecodesTheRfcsTestVectors) {
  EXPECT_EQ(decode_base64(""), "");
  EXPECT_EQ(decode_base64("Zg=="), "f");
  EXPECT_EQ(decode_base64("Zm8="), "fo");
  EXPECT_EQ(decode_base64("Zm9v"), "foo");
  EXPECT_EQ(decode_base64("Zm9vYg=="), "foob");
  EXPECT_EQ(decode_base64("Zm9vYmE="), "fooba");
  EXPECT_EQ(decode_base64("Zm9vYmFy"), "foobar");
}

TEST(Base64, DecodesEveryByteValue) {
  // The bytes 0 to 255 in order, as Python's base64.b64encode(bytes(range(256))) writes them.
  const std::string encoded =
      "AAECAwQFBgcICQoLDA0ODxAREhMUFRYXGBkaGxwdHh8gISIjJCUmJygpKissLS4vMDEyMzQ1Njc4OTo7PD0+P0BBQk"
      "NERUZHSElKS0xNTk9QUVJTVFVWV1hZWltcXV5fYGFiY2RlZmdoaWprbG1ub3BxcnN0dXZ3eHl6e3x9fn+AgYKDhIWG"
      "h4iJiouMjY6PkJGSk5SVlpeYmZqbnJ2en6ChoqOkpaanqKmqq6ytrq+wsbKztLW2t7i5uru8vb6/wMHCw8TFxsfIyc"
      "rLzM3Oz9DR0tPU1dbX2Nna29zd3t/g4eLj5OXm5+jp6uvs7e7v8PHy8/T19vf4+fr7/P3+/w==";
  const std::optional<std::string> bytes = decode_base64(encoded);
  ASSERT_TRUE(bytes.has_value());
  ASSERT_EQ(bytes->size(), 256u);
  for (int i = 0; i < 256; ++i) EXPECT_EQ(static_cast<unsigned char>((*bytes)[i]), i) << i;
}

TEST(Base64, RefusesWhatIsNotBase64) {
  EXPECT_FALSE(decode_base64("Zm9"));       // not a multiple of 4
  EXPECT_FALSE(decode_base64("Zm9v!A=="));  // a character outside the alphabet
  EXPECT_FALSE(decode_base64("Zg==Zm9v"));  // padding before the end
  EXPECT_FALSE(decode_base64("Zm 9v"));     // a space
  EXPECT_FALSE(decode_base64("Z==="));      // three padding characters
}

}  // namespace
}  // namespace fl
