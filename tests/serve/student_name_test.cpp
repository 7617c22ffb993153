// The server's rule for a student's name against the cases the page is held to as well
// (tests/data/student_names.json; web/tests/student_name.test.mjs): one rule for both.
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "serve/api_requests.hpp"

namespace fl::serve {
namespace {

TEST(StudentName, TheServerDecidesTheSharedCasesAsThePageDoes) {
  std::ifstream in(std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/tests/data/student_names.json");
  const nlohmann::json cases = nlohmann::json::parse(in);
  ASSERT_GE(cases["accepted"].size(), 5u);
  ASSERT_GE(cases["refused"].size(), 5u);
  for (const std::string name : cases["accepted"]) EXPECT_TRUE(is_student_name(name)) << name;
  for (const std::string name : cases["refused"]) EXPECT_FALSE(is_student_name(name)) << name;
}

}  // namespace
}  // namespace fl::serve
