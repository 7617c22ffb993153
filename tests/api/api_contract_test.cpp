// The web API's checker (api/api_contract.hpp) on bodies with a known verdict, and the declaration
// it reads (api/api_fields.hpp) whole: every type a key names is declared.
#include "api/api_contract.hpp"

#include <gtest/gtest.h>

#include <string>

#include "api/api_fields.hpp"

namespace fl::api {
namespace {

using nlohmann::json;

json contact() {
  return {{"normal", 0.3}, {"friction", -0.1}};
}

json estimate() {
  return {{"periods_used", 4}, {"periods_discarded", 1}, {"pulses", 6},
          {"period", 0.79},    {"period_sd", 0.001},     {"period_se", 0.0005},
          {"mu_k", 0.29},      {"mu_k_err", 0.007},      {"mu_k_err_worst", 0.009}};
}

TEST(ApiContract, ABodyAsDeclaredHasNoProblem) {
  EXPECT_TRUE(contract_problems(contact(), "ContactForce", "c").empty());
  EXPECT_TRUE(contract_problems(estimate(), "Estimate", "e").empty());
  EXPECT_TRUE(
      contract_problems(json::array({contact(), contact()}), "ContactForce[]", "c").empty());
}

TEST(ApiContract, AMissingKeyAnUndeclaredOneAndAWrongTypeAreEachNamed) {
  json e = estimate();
  e.erase("pulses");
  e["pulse_count"] = 6;
  e["period"] = "0.79";
  const auto problems = contract_problems(e, "Estimate", "state.estimate");
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0], "state.estimate.pulses: declared, but not there");
  EXPECT_EQ(problems[1], "state.estimate.period: expected a number, found \"0.79\"");
  EXPECT_NE(problems[2].find("state.estimate.pulse_count: not declared for Estimate"),
            std::string::npos);
}

TEST(ApiContract, NullIsTakenOnlyWhereTheKeyIsNullable) {
  json e = estimate();
  e["period_sd"] = nullptr;  // nullable: below two periods
  EXPECT_TRUE(contract_problems(e, "Estimate", "e").empty());
  e["period"] = nullptr;
  const auto problems = contract_problems(e, "Estimate", "e");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "e.period: null, but not declared nullable");
}

TEST(ApiContract, UnionsAndTuplesAreCheckedByValueAndLength) {
  EXPECT_TRUE(contract_problems(0.25, "PlaybackSpeed", "speed").empty());
  EXPECT_EQ(contract_problems(0.5, "PlaybackSpeed", "speed").size(), 1u);
  EXPECT_TRUE(contract_problems("receiving", "BoardPortState", "state").empty());
  EXPECT_EQ(contract_problems("listening", "BoardPortState", "state").size(), 1u);
  EXPECT_TRUE(contract_problems(json::array({0.1, 0.9, 0.8, true}), "PeriodRow", "p").empty());
  EXPECT_EQ(contract_problems(json::array({0.1, 0.9, 0.8}), "PeriodRow", "p").size(), 1u);
  EXPECT_EQ(contract_problems(json::array({0.1, 0.9, 0.8, 1}), "PeriodRow", "p").size(), 1u);
}

TEST(ApiContract, TheRunSummaryIsHeldToTheRunsFields) {
  // Keys the run's declaration leaves out when null may be absent; any other is named.
  const auto problems = contract_problems(json{{"scene", "minimal"}}, "RunSummaryJson", "done");
  EXPECT_GT(problems.size(), 20u);
  for (const std::string& p : problems) EXPECT_EQ(p.find("interrupted_at_s"), std::string::npos);
}

// A body that reaches every type `type` names: an array's element, each of a tuple's items.
json probe(const std::string& type) {
  if (type.ends_with("[]")) return json::array({probe(type.substr(0, type.size() - 2))});
  if (type.front() == '[') {
    json items = json::array();
    std::size_t from = 1;
    for (std::size_t comma; (comma = type.find(',', from)) != std::string::npos; from = comma + 1)
      items.push_back(probe(type.substr(from, comma - from)));
    items.push_back(probe(type.substr(from, type.size() - 1 - from)));
    return items;
  }
  return json::object();
}

// Every type a key or alias names is a declared object or alias, or a type the checker knows: a
// typo in the declaration fails here, not in the page's compiler.
TEST(ApiDeclaration, EveryTypeNamedIsDeclared) {
  const ApiDeclaration& d = api_declaration();
  const auto undeclared = [](const std::string& type) {
    std::string out;
    for (const std::string& p : contract_problems(probe(type), type, type))
      if (p.find("is not declared") != std::string::npos) out += p + "\n";
    return out;
  };
  for (const ApiObject& o : d.objects)
    for (const ApiKey& k : o.keys) EXPECT_EQ(undeclared(k.type), "") << o.name << "." << k.name;
  for (const ApiAlias& a : d.aliases) EXPECT_EQ(undeclared(a.type), "") << a.name;
  // And the probe finds a typo.
  EXPECT_NE(undeclared("[number, Contactforce][]"), "");
}

TEST(ApiDeclaration, ItsJsonFormListsEveryObjectWithItsKeysInOrder) {
  const json d = api_declaration_json();
  ASSERT_TRUE(d["objects"].contains("ClassRow"));
  const json& row = d["objects"]["ClassRow"];
  EXPECT_EQ(row[0]["name"], "session");
  EXPECT_EQ(row[5]["csv"], "spacing_mm");
  EXPECT_EQ(row[5]["csv_scale"], 1e3);
  EXPECT_TRUE(d["objects"].contains("RunSummaryJson"));
  EXPECT_EQ(d["aliases"]["PlaybackSpeed"], "1 | 0.25 | 0.0625");
}

}  // namespace
}  // namespace fl::api
