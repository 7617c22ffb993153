// What serve's C++ writes, held to the web API's one declaration (api/api_fields.hpp): every body
// of every route, on the wire, and the rig of every shipped scene. The page's types are generated
// from the same declaration, and its mock server is held to it too
// (web/tests/mock_contract.test.mjs).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/api_contract.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/session_request.hpp"
#include "lab_server_fixture.hpp"
#include "serve/api_json.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

std::string problems_of(const json& body, const std::string& type, const std::string& path) {
  std::string out;
  for (const std::string& p : api::contract_problems(body, type, path)) out += p + "\n";
  return out;
}

// The scenes folder's and its catalogues' (extreme/, imperfect/): a server may offer any of them.
TEST(ServerContract, EveryShippedScenesRigIsAsDeclared) {
  const std::filesystem::path scenes =
      std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / "scenes";
  std::size_t checked = 0;
  for (const auto& folder : {scenes, scenes / "extreme", scenes / "imperfect"})
    for (const SceneEntry& entry : list_scenes(folder.string())) {
      const PreparedSession prepared =
          prepare_session({entry.name, {}}, folder.string(), FRICTIONLAB_TEST_ASSET_DIR);
      const json rig = rig_json(entry.name, *prepared.rig, prepared.accepts,
                                paper_table_in(FRICTIONLAB_TEST_ASSET_DIR));
      EXPECT_EQ(problems_of(rig, "Rig", entry.name), "");
      ++checked;
    }
  EXPECT_GT(checked, 20u);
}

TEST_F(LabServerTest, EveryBodyTheServerSendsIsAsDeclared) {
  const auto lab = client_->Get("/api/lab");
  ASSERT_TRUE(lab);
  EXPECT_EQ(problems_of(json::parse(lab->body), "Lab", "lab"), "");

  const auto created = post(
      "/api/sessions", {{"scene", "minimal"}, {"set", {"world.duration=6s"}}, {"name", "Ada"}});
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 201);
  const json session = json::parse(created->body);
  EXPECT_EQ(problems_of(session, "Session", "session"), "");
  const std::string id = session["id"];
  keys_[id] = session["key"];
  const std::string paper = start({{"scene", "paper-rig"}});
  const auto refused =
      post("/api/sessions", {{"scene", "minimal"}, {"set", {"rollers.spacing=-5mm"}}});
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);
  EXPECT_EQ(problems_of(json::parse(refused->body), "ErrorBody", "refused"), "");

  const auto speed = command(id, {{"speed", 0.25}});
  EXPECT_EQ(problems_of(json::parse(speed->body), "ControlReply", "control"), "");
  ASSERT_EQ(command(id, {{"speed", 1}})->status, 200);
  const auto play = command(id, {{"action", "play"}});
  EXPECT_EQ(problems_of(json::parse(play->body), "ControlReply", "control"), "");
  std::size_t states = 0;
  std::size_t estimated = 0;  // states whose estimate is filled, not null
  bool done = false;
  for (const auto& [name, data] : stream_to_done(id)) {
    if (name == "state") {
      ++states;
      estimated += data["estimate"].is_object() ? 1 : 0;
      EXPECT_EQ(problems_of(data, "LabState", "state"), "");
    } else if (name == "done") {
      done = true;
      EXPECT_EQ(problems_of(data, "RunSummaryJson", "done"), "");
    } else if (name == "failed") {
      EXPECT_EQ(problems_of(data, "Failure", "failed"), "");
    }
  }
  EXPECT_GT(states, 10u);
  EXPECT_GT(estimated, 0u);
  EXPECT_TRUE(done);
  const auto classes = client_->Get("/api/class");
  ASSERT_TRUE(classes);
  const json table = json::parse(classes->body);
  EXPECT_EQ(problems_of(table, "ClassTable", "class"), "");
  ASSERT_EQ(table["sessions"].size(), 2u);
  const auto rig = client_->Get("/api/rig");
  ASSERT_TRUE(rig);
  EXPECT_EQ(problems_of(json::parse(rig->body), "LiveRig", "rig"), "");
  const auto missing = client_->Get("/api/sessions/0123/files/summary.json");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(problems_of(json::parse(missing->body), "ErrorBody", "missing"), "");
  EXPECT_FALSE(paper.empty());
}

// A small server: one session at most.
class FullServerTest : public LabServerTest {
 protected:
  FullServerTest() { max_sessions_ = 1; }
};

TEST_F(FullServerTest, ARefusalOfAFullLabIsAsDeclared) {
  start({{"scene", "minimal"}});
  const auto full = post("/api/sessions", {{"scene", "minimal"}});
  ASSERT_TRUE(full);
  ASSERT_EQ(full->status, 503);
  const json body = json::parse(full->body);
  EXPECT_EQ(body["refused"], true);
  EXPECT_EQ(problems_of(body, "ErrorBody", "full"), "");
}

}  // namespace
}  // namespace fl::serve
