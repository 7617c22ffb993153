// A value and its uncertainty as the lab prints them, against the cases the page is held to as
// well (tests/data/plus_minus_cases.json): never "+- 0.0000" for an uncertainty that is not zero,
// one significant digit or two where it is a 1.
#include "io/plus_minus.hpp"

#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fl {
namespace {

TEST(PlusMinus, EveryFrontEndsCases) {
  std::ifstream in(std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/data/plus_minus_cases.json");
  const nlohmann::json cases = nlohmann::json::parse(in)["cases"];
  ASSERT_GE(cases.size(), 10u);
  for (const nlohmann::json& c : cases)
    EXPECT_EQ(plus_minus(c["value"], c["uncertainty"], c["min_decimals"]), c["text"]) << c.dump();
}

TEST(PlusMinus, AFrameSpellsItsSignAsTheFontHasIt) {
  EXPECT_EQ(plus_minus(0.7912, 0.0038, 3, "\u00b1"), "0.791 \u00b1 0.004");
}

TEST(PlusMinus, AMissingUncertaintyPrintsAsItIs) {
  EXPECT_EQ(plus_minus(0.3, std::numeric_limits<double>::quiet_NaN(), 2), "0.30 +- nan");
}

}  // namespace
}  // namespace fl
