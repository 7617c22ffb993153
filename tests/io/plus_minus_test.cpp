// A value and its uncertainty as the lab prints them: never "+- 0.0000" for an uncertainty that
// is not zero.
#include "io/plus_minus.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace fl {
namespace {

TEST(PlusMinus, TheUncertaintyAlwaysShowsTwoSignificantDigits) {
  EXPECT_EQ(plus_minus(0.2948, 0.0021, 4), "0.2948 +- 0.0021");
  EXPECT_EQ(plus_minus(0.29482314, 0.0000134, 4), "0.294823 +- 0.000013");
  EXPECT_EQ(plus_minus(0.7967, 0.00004, 4), "0.796700 +- 0.000040");
  // Larger uncertainties keep the decimals asked for.
  EXPECT_EQ(plus_minus(1.7001, 0.038, 4), "1.7001 +- 0.0380");
  // An exact value (0) and a missing one (NaN) print as they are.
  EXPECT_EQ(plus_minus(0.3, 0.0, 4), "0.3000 +- 0.0000");
  EXPECT_EQ(plus_minus(0.3, std::numeric_limits<double>::quiet_NaN(), 2), "0.30 +- nan");
}

}  // namespace
}  // namespace fl
