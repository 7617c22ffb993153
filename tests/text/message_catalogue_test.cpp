// The lab's reading of a Fluent catalogue: simple messages, multiline ones, variables and
// literals filled; what it does not read (selectors, terms, attributes) skipped whole, never read
// half; a missing variable left visible rather than silently empty.
#include "text/message_catalogue.hpp"

#include <gtest/gtest.h>

namespace fl {
namespace {

const char* kFtl = R"(# A comment
## A group comment
language-name = Français
report-title = Compte rendu : l'oscillateur à frottement
report-period = T = { $value } s, sur { $count } périodes
report-method =
    Une plaque repose sur deux rouleaux
    qui tournent en sens opposés.

    Elle oscille.
report-brace = Accolade : { "{" }
-term = a term
emails = { $n ->
    [one] one email
   *[other] { $n } emails
}
button = Lire
    .aria-label = Lire la simulation
after = la suite
)";

TEST(MessageCatalogue, ReadsTheMessagesTheLabUses) {
  const MessageCatalogue c = MessageCatalogue::parse(kFtl);
  EXPECT_EQ(c.format("language-name"), "Français");
  EXPECT_EQ(c.format("report-title"), "Compte rendu : l'oscillateur à frottement");
  EXPECT_EQ(c.format("report-period", {{"value", "0,7766"}, {"count", "10"}}),
            "T = 0,7766 s, sur 10 périodes");
  EXPECT_EQ(c.format("report-method"),
            "Une plaque repose sur deux rouleaux qui tournent en sens opposés. Elle oscille.");
  EXPECT_EQ(c.format("report-brace"), "Accolade : {");
  EXPECT_EQ(c.format("after"), "la suite");
}

TEST(MessageCatalogue, SkipsWhatItDoesNotRead) {
  const MessageCatalogue c = MessageCatalogue::parse(kFtl);
  EXPECT_FALSE(c.has("emails"));  // a selector: the page's
  EXPECT_FALSE(c.has("-term"));
  EXPECT_FALSE(c.has("term"));
  // A message with attributes keeps its value, never an attribute's text.
  EXPECT_EQ(c.format("button"), "Lire");
  EXPECT_EQ(c.format("nothing"), std::nullopt);
}

TEST(MessageCatalogue, AMissingVariableStaysVisible) {
  const MessageCatalogue c = MessageCatalogue::parse(kFtl);
  EXPECT_EQ(c.format("report-period", {{"value", "1"}}), "T = 1 s, sur {$count} périodes");
}

TEST(MessageCatalogue, AnythingParsesWithoutThrowing) {
  for (const char* text : {"", "=", "a =", "a = {", "a = { $", "a = }", "\n\n  x = y", "a = {}"})
    EXPECT_NO_THROW(MessageCatalogue::parse(text)) << text;
  EXPECT_FALSE(MessageCatalogue::parse("a = {").has("a"));
  EXPECT_FALSE(MessageCatalogue::parse("a = }").has("a"));
}

}  // namespace
}  // namespace fl
