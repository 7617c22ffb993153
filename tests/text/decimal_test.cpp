// The decimal reader the browser's build uses (strtod on the number's text) held to the host's
// std::from_chars for double: the same end, the same error and the same bits, for numbers as
// people write them, for every double printed exactly, and for text that is no number.
#include "text/decimal.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace fl {
namespace {

void expect_same_as_from_chars(const std::string& text) {
  double expected = -12345.0;
  double found = -12345.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto want = std::from_chars(first, last, expected);
  const auto got = read_decimal_by_strtod(first, last, found);
  EXPECT_EQ(got.ec, want.ec) << '"' << text << '"';
  EXPECT_EQ(got.ptr - first, want.ptr - first) << '"' << text << '"';
  if (std::isnan(expected))
    EXPECT_TRUE(std::isnan(found)) << '"' << text << '"';
  else
    EXPECT_EQ(std::bit_cast<std::uint64_t>(found), std::bit_cast<std::uint64_t>(expected))
        << '"' << text << '"';
}

TEST(Decimal, ReadsWhatPeopleWriteAsFromCharsDoes) {
  const std::vector<std::string> texts = {"0",
                                          "-0",
                                          "89",
                                          "89 mm",
                                          "0.776",
                                          ".5",
                                          "5.",
                                          "-.5e2",
                                          "1e3",
                                          "1E-3s",
                                          "1e",
                                          "1e+",
                                          "1e+5x",
                                          "2.5e-3",
                                          "0.1",
                                          "0.3",
                                          "3.141592653589793238",
                                          "1e308",
                                          "1e309",
                                          "-1e309",
                                          "4.9e-324",
                                          "1e-400",
                                          "2e-320",
                                          "inf",
                                          "-Infinity",
                                          "INFx",
                                          "nan",
                                          "nan(123)",
                                          "nan(",
                                          "NaN()",
                                          "",
                                          "-",
                                          ".",
                                          "+1",
                                          " 1",
                                          "0x1p3",
                                          "e5",
                                          "--1",
                                          "1..2",
                                          "1,5",
                                          "12 345",
                                          "007",
                                          "1e0000000000000000000001",
                                          "0.000000000000000000000000000000000000000000001e300"};
  for (const std::string& text : texts) expect_same_as_from_chars(text);
}

TEST(Decimal, ReadsEveryDoublePrintedExactlyToItsBits) {
  std::mt19937_64 bits(20261129);
  char buffer[64];
  for (int i = 0; i < 20000; ++i) {
    const double value = std::bit_cast<double>(bits());
    if (!std::isfinite(value)) continue;
    std::snprintf(buffer, sizeof buffer, i % 2 ? "%.17g" : "%.6e", value);
    expect_same_as_from_chars(buffer);
  }
}

TEST(Decimal, AgreesOnTextThatIsHalfANumber) {
  std::mt19937_64 draws(7);
  const std::string alphabet = "0123456789.-+eEinfa x";
  for (int i = 0; i < 20000; ++i) {
    std::string text;
    const std::size_t length = 1 + draws() % 8;
    for (std::size_t k = 0; k < length; ++k) text += alphabet[draws() % alphabet.size()];
    expect_same_as_from_chars(text);
  }
}

}  // namespace
}  // namespace fl
