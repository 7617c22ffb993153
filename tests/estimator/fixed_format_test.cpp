// The firmware's number printing, shared with the host so that both print the same text.
#include "estimator/fixed_format.h"

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

namespace fl {
namespace {

std::string fixed(float v, uint8_t decimals) {
  char buf[24];
  const uint8_t n = fl_estimator::format_fixed(buf, v, decimals);
  EXPECT_EQ(std::string(buf).size(), n);
  return buf;
}

std::string whole(uint32_t v, uint8_t min_digits = 1) {
  char buf[12];
  const uint8_t n = fl_estimator::format_uint(buf, v, min_digits);
  EXPECT_EQ(std::string(buf).size(), n);
  return buf;
}

TEST(FixedFormat, Integers) {
  EXPECT_EQ(whole(0), "0");
  EXPECT_EQ(whole(7), "7");
  EXPECT_EQ(whole(10), "10");
  EXPECT_EQ(whole(1000000), "1000000");
  EXPECT_EQ(whole(4294967295u), "4294967295");
  EXPECT_EQ(whole(42, 5), "00042");
  EXPECT_EQ(whole(0, 3), "000");
}

TEST(FixedFormat, FixedPoint) {
  EXPECT_EQ(fixed(0.0f, 0), "0");
  EXPECT_EQ(fixed(0.0f, 1), "0.0");
  EXPECT_EQ(fixed(1234.5f, 1), "1234.5");
  EXPECT_EQ(fixed(0.28722f, 5), "0.28722");
  EXPECT_EQ(fixed(0.004f, 2), "0.00");
  EXPECT_EQ(fixed(0.006f, 2), "0.01");
  EXPECT_EQ(fixed(9.99f, 1), "10.0");
  EXPECT_EQ(fixed(-3.25f, 2), "-3.25");
  EXPECT_EQ(fixed(249979.9f, 1), "249979.9");
  EXPECT_EQ(fixed(1e12f, 1), "ovf");
  EXPECT_EQ(fixed(1.5f, 9), "1.500000");  // at most 6 decimals
}

}  // namespace
}  // namespace fl
