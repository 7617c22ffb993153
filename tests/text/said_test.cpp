// The lab's messages in English, from the catalogue compiled in (assets/locales/en.ftl): values
// put where the pattern names them, numbers with six significant digits as describe() writes
// them, a message quoted inside another, and a message the catalogue lacks saying so.
#include "text/said.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "text/english_catalogue.hpp"

namespace fl {
namespace {

TEST(Said, PutsEachValueWhereTheEnglishPatternNamesIt) {
  EXPECT_EQ(
      english(said("check-rollers-overlap", {arg("radii_mm", 20.0), arg("spacing_mm", 15.0)})),
      "the rollers overlap: l = 15 mm is not more than their radii's sum 20 mm");
}

TEST(Said, WritesNumbersWithSixSignificantDigits) {
  EXPECT_EQ(english(said("check-must-be-positive", {arg("value", -0.123456789)})),
            "must be positive, found -0.123457");
  EXPECT_EQ(
      english(said("check-duration-steps", {arg("steps", 2.5e9)})),
      "needs 2.5e+09 steps, more than 1e9; use a larger world.time_step or a shorter duration");
  EXPECT_EQ(english(said("check-solver-iterations", {arg("iterations", 0)})),
            "must be between 1 and 10000, found 0");
}

TEST(Said, RoundsAMeasuredValueAsEveryLanguageShowsIt) {
  EXPECT_EQ(to_significant_digits(0.0123456, 3), 0.0123);
  EXPECT_EQ(to_significant_digits(98765.4, 3), 98800.0);
  EXPECT_EQ(to_significant_digits(-2.71828, 2), -2.7);
  EXPECT_TRUE(std::isinf(to_significant_digits(std::numeric_limits<double>::infinity(), 3)));
  EXPECT_EQ(to_decimal_places(0.77639, 4), 0.7764);
  EXPECT_EQ(to_decimal_places(12.5, 0), 13.0);  // half away from zero
}

TEST(Said, QuotesAMessageInsideAnother) {
  const Said range =
      said("check-implausible",
           {arg("what", said("quantity-spacing")), arg("least", 1.0), arg("most", 2000.0),
            arg("unit", " mm"), arg("paper", said("paper-spacing")), arg("value", 89000.0)});
  EXPECT_EQ(english(said("check-implausible-value", {arg("why", range)})),
            "expected the roller spacing l from 1 to 2000 mm (the paper's rig: 89 mm), found "
            "89000 mm; check the value and its unit (a plain number is SI)");
}

TEST(Said, AMessageTheCatalogueLacksSaysSo) {
  const std::string text = english(said("no-such-message"));
  EXPECT_NE(text.find("no-such-message"), std::string::npos) << text;
  EXPECT_NE(text.find("lacks"), std::string::npos) << text;
}

TEST(Said, TheCompiledCatalogueIsEnglishsWhole) {
  const std::string_view text = english_catalogue_text();
  EXPECT_TRUE(text.starts_with("# frictionlab's words in English")) << text.substr(0, 60);
  EXPECT_NE(text.find("\nlanguage-name = English\n"), std::string_view::npos);
  EXPECT_NE(text.find("\nreport-footer = "), std::string_view::npos);  // its last part, too
}

}  // namespace
}  // namespace fl
