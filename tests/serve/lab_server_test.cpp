// The server in-process on an ephemeral port, through a real HTTP client: what the page is
// offered, sessions whose run is `run`'s (the same summary and files, byte for byte), refusals by
// field, controls, and bad input that costs only the client who sent it.
#include "serve/lab_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "io/csv_table.hpp"
#include "lab/run/run_outputs.hpp"
#include "lab_server_fixture.hpp"
#include "support/scene_fixture.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

TEST_F(LabServerTest, OffersTheFoldersScenesByNameAndThePapersMaterials) {
  const auto res = client_->Get("/api/lab");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const json lab = json::parse(res->body);
  ASSERT_EQ(lab["scenes"].size(), 2u);
  EXPECT_EQ(lab["scenes"][0]["name"], "minimal");
  EXPECT_EQ(lab["scenes"][1]["name"], "paper-rig");
  EXPECT_FALSE(lab["scenes"][1]["title"].get<std::string>().empty());
  // Table I: LEGO blocks at 300 K and 77 K, iron at 300 K only.
  bool lego = false, iron = false;
  for (const json& m : lab["materials"]) {
    if (m["key"] == "lego") lego = m["temperatures_k"] == json::array({300.0, 77.0});
    if (m["key"] == "iron") iron = m["temperatures_k"] == json::array({300.0});
  }
  EXPECT_TRUE(lego);
  EXPECT_TRUE(iron);
  // The page, and the LEGO parts the 3D view loads.
  const auto page = client_->Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  // A browser that accepts brotli gets gzip: the library's brotli runs at its slowest quality.
  const auto zipped = client_->Get("/", {{"Accept-Encoding", "gzip, deflate, br"}});
  ASSERT_TRUE(zipped);
  EXPECT_EQ(zipped->get_header_value("Content-Encoding"), "gzip");
  EXPECT_NE(zipped->body.find("<title>frictionlab</title>"), std::string::npos);
  const auto part = client_->Get("/parts/brick-2x4.glb");
  ASSERT_TRUE(part);
  EXPECT_EQ(part->status, 200);
  EXPECT_EQ(part->body.substr(0, 4), "glTF");
}

TEST_F(LabServerTest, ASessionsRunIsTheRunsSummaryAndFilesByteForByte) {
  const std::vector<std::string> set{"world.duration=1.5s", "rollers.spacing=70mm"};
  const std::string id = start({{"scene", "minimal"}, {"set", set}});
  ASSERT_FALSE(id.empty());
  ASSERT_EQ(command(id, {{"action", "play"}})->status, 200);
  const auto events = stream_to_done(id);
  ASSERT_FALSE(events.empty());
  ASSERT_EQ(events.back().first, "done");

  // The same set-up run as `frictionlab run minimal.yaml --set ...` runs it.
  const Scene scene = test::scene_file(
      "minimal.yaml",
      std::vector<SceneOverride>{{"world.duration", "1.5s"}, {"rollers.spacing", "70mm"}});
  const CompiledRig rig = compile_rig(scene);
  const RunOptions options = recording_for(scene.output);
  RunRecording recording;
  const RunSummary summary = run_experiment(rig, options, &recording);
  EXPECT_EQ(events.back().second, summary_json(summary));
  for (const auto& [name, text] : run_output_files(scene.output, rig, summary, recording)) {
    if (name == "timing.json") continue;
    const auto file = client_->Get(session(id, "/files/" + name).c_str());
    ASSERT_TRUE(file);
    EXPECT_EQ(file->status, 200) << name;
    EXPECT_TRUE(file->body == text) << name << " differs from run's";
  }
  // The states came in order, the Hall samples each once: 1 kHz over 1.5 s.
  std::size_t samples = 0;
  double previous = -1.0;
  for (const auto& [name, data] : events) {
    if (name != "state") continue;
    EXPECT_GE(data["t"].get<double>(), previous);
    previous = data["t"].get<double>();
    samples += data["hall"].size();
  }
  EXPECT_NEAR(static_cast<double>(samples), 1500.0, 2.0);
}

TEST_F(LabServerTest, ABadSetEntryIsRefusedByFieldWithTheEntry) {
  const auto res = post("/api/sessions", {{"scene", "minimal"}, {"set", {"rollers.spacing=-5mm"}}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  const json body = json::parse(res->body);
  ASSERT_EQ(body["problems"].size(), 1u);
  EXPECT_EQ(body["problems"][0]["field"], "set");
  EXPECT_EQ(body["problems"][0]["value"], "rollers.spacing=-5mm");
  EXPECT_NE(body["problems"][0]["message"].get<std::string>().find("positive"), std::string::npos);
  // An unknown key says the one it was near.
  const auto typo = post("/api/sessions", {{"scene", "minimal"}, {"set", {"rollers.spacng=5mm"}}});
  ASSERT_TRUE(typo);
  EXPECT_EQ(typo->status, 400);
  EXPECT_NE(typo->body.find("did you mean 'spacing'"), std::string::npos);
}

TEST_F(LabServerTest, AScenesNameIsNeverAPath) {
  for (const std::string scene : {"../scenes/minimal", "/etc/passwd", "minimal.yaml", ""}) {
    const auto res = post("/api/sessions", {{"scene", scene}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << scene;
    const json body = json::parse(res->body);
    EXPECT_EQ(body["problems"][0]["field"], "scene") << scene;
  }
  // Nor does a file's path reach outside the page's folder.
  for (const char* path :
       {"/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/parts/../parts.yaml"}) {
    const auto res = client_->Get(path);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 404) << path;
  }
}

TEST_F(LabServerTest, BadRequestsCostTheirClientAnErrorAndTheServerGoesOn) {
  for (const std::string body : {"", "garbage", "[1,2]", R"({"set": []})", R"({"scene": 3})",
                                 R"({"scene": "minimal", "set": "rollers.spacing=70mm"})",
                                 R"({"scene": "minimal", "set": [1]})"}) {
    const auto res = client_->Post("/api/sessions", body, "application/json");
    ASSERT_TRUE(res) << body;
    EXPECT_EQ(res->status, 400) << body;
    EXPECT_TRUE(json::parse(res->body).contains("error")) << body;
  }
  // Garbage bytes on a raw connection, and a client that vanishes mid-stream.
  std::mt19937 bytes(7);
  std::string noise(100000, '\0');
  for (char& c : noise) c = static_cast<char>(bytes());
  send_raw(noise, /*wait_for_answer=*/false);
  const std::string id = start({{"scene", "minimal"}});
  {
    httplib::Client leaver("127.0.0.1", port_);
    int chunks = 0;
    leaver.Get(session(id, "/stream").c_str(),
               [&](const char*, std::size_t) { return ++chunks < 3; });
  }
  const auto res = client_->Get("/api/lab");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(server_->sessions(), 1);
}

TEST_F(LabServerTest, ControlsPlayPauseStepResetAndSlowDown) {
  const std::string id = start({{"scene", "minimal"}});
  // A step while paused advances one frame's worth of simulated time, 1/30 s.
  ASSERT_EQ(command(id, {{"action", "step"}})->status, 200);
  std::string buffer;
  httplib::Client reader("127.0.0.1", port_);
  json first;
  reader.Get(session(id, "/stream").c_str(), [&](const char* data, std::size_t n) {
    buffer.append(data, n);
    const auto end = buffer.find("\n\n");
    if (end == std::string::npos) return true;
    first = json::parse(buffer.substr(buffer.find("data: ") + 6, end - buffer.find("data: ") - 6));
    return false;
  });
  // The run stops at the first 1 ms step at or past it.
  EXPECT_NEAR(first["t"].get<double>(), 1.0 / 30, 1e-3 + 1e-12);
  EXPECT_FALSE(first["playing"].get<bool>());
  const json slow = json::parse(command(id, {{"speed", 0.0625}})->body);
  EXPECT_EQ(slow["speed"], 0.0625);
  const json reset = json::parse(command(id, {{"action", "reset"}})->body);
  EXPECT_EQ(reset["t"], 0.0);
  EXPECT_FALSE(reset["playing"].get<bool>());
  // What it does not know: 400, saying what it takes.
  for (const json& bad :
       {json{{"speed", 4}}, json{{"speed", "fast"}}, json{{"action", "jump"}}, json::object()}) {
    const auto res = command(id, bad);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad.dump();
  }
  // A session that is not there.
  const auto gone = post("/api/sessions/0123456789abcdef/control", {{"action", "play"}});
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->status, 404);
  // No files before the run's end.
  const auto early = client_->Get(session(id, "/files/summary.json").c_str());
  ASSERT_TRUE(early);
  EXPECT_EQ(early->status, 404);
  ASSERT_EQ(end(id)->status, 200);
  EXPECT_EQ(server_->sessions(), 0);
}

TEST_F(LabServerTest, ALongRunKeepsItsSummaryButNotItsStepsSoNoSetUpGrowsTheServer) {
  // A server beside the fixture's that records runs up to 1 s: a 1.5 s run keeps its summary and
  // cycles only.
  ServeOptions options;
  options.port = 0;
  options.scenes_dir = (dir_ / "scenes").string();
  options.web_dir = (dir_ / "web").string();
  options.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
  options.most_recorded_seconds = 1.0;
  LabServer brief(options);
  const int port = brief.bind();
  std::thread serving([&brief] { brief.listen(); });
  port_ = port;
  client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
  const std::string id = start({{"scene", "minimal"}, {"set", {"world.duration=1.5s"}}});
  ASSERT_EQ(command(id, {{"action", "play"}})->status, 200);
  const auto events = stream_to_done(id);
  ASSERT_EQ(events.back().first, "done");
  // The summary is the run's, recorded or not.
  const Scene scene =
      test::scene_file("minimal.yaml", std::vector<SceneOverride>{{"world.duration", "1.5s"}});
  EXPECT_EQ(events.back().second, summary_json(run_experiment(compile_rig(scene), RunOptions{})));
  EXPECT_EQ(client_->Get(session(id, "/files/summary.json").c_str())->status, 200);
  for (const char* name : {"trajectory.csv", "hall.csv", "periods.csv"}) {
    const auto res = client_->Get(session(id, std::string("/files/") + name).c_str());
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 404) << name;
    EXPECT_NE(res->body.find("longer than 1 s"), std::string::npos) << res->body;
  }
  brief.stop();
  serving.join();
}

TEST(LabServerStop, StopsAServerThatHasNotBegunToListen) {
  ServeOptions options;
  options.port = 0;
  options.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
  for (int i = 0; i < 20; ++i) {
    LabServer server(options);
    server.bind();
    std::thread serving([&server] { server.listen(); });
    server.stop();  // at once: before, during or after listen() begins
    serving.join();
  }
}

// A small shared server: two sessions at most, and a token.
class SharedServerTest : public LabServerTest {
 protected:
  SharedServerTest() {
    max_sessions_ = 2;
    token_ = "s3cret";
  }
};

TEST_F(SharedServerTest, TheApiAnswersOnlyToTheToken) {
  const auto without = client_->Get("/api/lab");
  ASSERT_TRUE(without);
  EXPECT_EQ(without->status, 403);
  EXPECT_NE(without->body.find("token"), std::string::npos);
  const auto wrong = client_->Get("/api/lab?token=guess");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 403);
  EXPECT_EQ(client_->Get("/api/lab?token=s3cret")->status, 200);
  EXPECT_EQ(client_->Get("/api/lab", {{"X-Frictionlab-Token", "s3cret"}})->status, 200);
  // The page and the parts need none: they tell nothing, and the page reads the token from its
  // own address.
  EXPECT_EQ(client_->Get("/")->status, 200);
  EXPECT_EQ(client_->Get("/parts/brick-2x4.glb")->status, 200);
  EXPECT_EQ(post("/api/sessions", {{"scene", "minimal"}})->status, 403);
}

TEST_F(SharedServerTest, APageBeyondTheLimitIsToldTheLabIsFull) {
  const std::string create = "/api/sessions?token=s3cret";
  std::vector<std::string> ids;
  for (int i = 0; i < 2; ++i) ids.push_back(start({{"scene", "minimal"}}, create));
  const auto full = post(create, {{"scene", "minimal"}});
  ASSERT_TRUE(full);
  EXPECT_EQ(full->status, 503);
  const json body = json::parse(full->body);
  EXPECT_EQ(body["refused"], true);
  EXPECT_NE(body["error"].get<std::string>().find("2 sessions"), std::string::npos);
  // One ends: the next page gets its session.
  ASSERT_EQ(end(ids[0], "?token=s3cret")->status, 200);
  EXPECT_EQ(post(create, {{"scene", "minimal"}})->status, 201);
  EXPECT_EQ(server_->sessions(), 2);
}

TEST_F(LabServerTest, TheClassTableListsEachSessionsSetUpAndResultInOrder) {
  const std::string ada = start({{"scene", "minimal"},
                                 {"set", {"plate.material=iron", "world.duration=3s"}},
                                 {"name", "Lovelace, Ada (2B)"}});
  const std::string bob = start({{"scene", "minimal"}, {"set", {"rollers.spacing=70mm"}}});
  // Names that are not names are refused, saying what a name is.
  for (const json& name : {json("=1+1"), json("a;b"), json(std::string(41, 'a')), json(3)}) {
    const auto res = post("/api/sessions", {{"scene", "minimal"}, {"name", name}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << name;
    const json refusal = json::parse(res->body);
    ASSERT_EQ(refusal["problems"].size(), 1u) << res->body;
    EXPECT_EQ(refusal["problems"][0]["field"], "name");
    EXPECT_NE(res->body.find("letters, digits"), std::string::npos) << res->body;
  }
  ASSERT_EQ(command(ada, {{"action", "play"}})->status, 200);
  const auto events = stream_to_done(ada);
  const json& summary = events.back().second;
  const json table = json::parse(client_->Get("/api/class")->body);
  ASSERT_EQ(table["sessions"].size(), 2u);
  const json& first = table["sessions"][0];
  EXPECT_EQ(first["session"], ada);
  EXPECT_EQ(first["name"], "Lovelace, Ada (2B)");
  EXPECT_EQ(first["material"], "Iron");
  EXPECT_EQ(first["state"], "done");
  EXPECT_EQ(first["spacing"], 0.089);
  // The done run's row is its summary's headline, and the paper's value beside it.
  // (The minimal rig has no Hall sensor: its period is the trajectory's, with no spread.)
  const auto headline = [&](const char* key) {
    const auto it = summary.find(key);
    return it == summary.end() ? json(nullptr) : *it;
  };
  EXPECT_EQ(first["period_from"], "trajectory");
  EXPECT_FALSE(first["period"].is_null());
  EXPECT_EQ(first["period"], headline("period_trajectory_s"));
  EXPECT_EQ(first["period_err"], headline("period_trajectory_err_s"));
  EXPECT_EQ(first["mu_k"], headline("mu_k_recovered"));
  EXPECT_EQ(first["mu_k_err"], headline("mu_k_err_quadrature"));
  EXPECT_EQ(first["paper_mu_k"], 0.42);
  const json& second = table["sessions"][1];
  EXPECT_EQ(second["session"], bob);
  EXPECT_EQ(second["name"], nullptr);
  EXPECT_EQ(second["state"], "paused");
  EXPECT_EQ(second["spacing"], 0.07);
  // Not measured: null, never 0.
  EXPECT_EQ(second["period"], nullptr);
  EXPECT_EQ(second["mu_k"], nullptr);
  EXPECT_EQ(table["rig"], nullptr);

  // The CSV: the columns docs/web-api.md lists, the same values, empty where JSON has null.
  const auto csv = client_->Get("/api/class.csv");
  ASSERT_TRUE(csv);
  EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
  const CsvTable rows = parse_csv_table(csv->body, "class.csv");
  std::vector<std::string> header;
  for (const CsvCell& c : rows.header) header.push_back(c.text);
  EXPECT_EQ(header, (std::vector<std::string>{"session", "name", "scene", "material",
                                              "temperature_k", "spacing_mm", "h_c_mm", "state",
                                              "t_s", "period_s", "period_err_s", "period_from",
                                              "mu_k", "mu_k_err", "paper_period_s", "paper_mu_k"}));
  ASSERT_EQ(rows.rows.size(), 2u);
  // A name with a comma is one quoted cell.
  EXPECT_NE(csv->body.find("\"Lovelace, Ada (2B)\""), std::string::npos);
  EXPECT_EQ(rows.rows[0][1].text, "Lovelace, Ada (2B)");
  EXPECT_EQ(std::stod(rows.rows[0][5].text), 89.0);
  EXPECT_NEAR(std::stod(rows.rows[0][9].text), headline("period_trajectory_s").get<double>(), 1e-9);
  EXPECT_EQ(rows.rows[0][11].text, "trajectory");
  EXPECT_EQ(rows.rows[1][9].text, "");
}

TEST_F(LabServerTest, AStudentNamedAfterTheSessionBeganReachesTheClassTable) {
  const std::string id = start({{"scene", "minimal"}});
  const auto row_name = [&] {
    const json table = json::parse(client_->Get("/api/class")->body);
    return table["sessions"][0]["name"];
  };
  EXPECT_EQ(row_name(), nullptr);
  const auto named = command(id, {{"name", "Curie, M. (2B)"}});
  ASSERT_TRUE(named);
  EXPECT_EQ(named->status, 200) << named->body;
  EXPECT_EQ(row_name(), "Curie, M. (2B)");
  // A name that is not one is refused by field, and the row keeps the name it had.
  const auto refused = command(id, {{"name", "=HYPERLINK(1)"}});
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);
  const json refusal = json::parse(refused->body);
  ASSERT_EQ(refusal["problems"].size(), 1u) << refused->body;
  EXPECT_EQ(refusal["problems"][0]["field"], "name");
  EXPECT_EQ(row_name(), "Curie, M. (2B)");
  // An empty name takes it away.
  EXPECT_EQ(command(id, {{"name", ""}})->status, 200);
  EXPECT_EQ(row_name(), nullptr);
}

TEST_F(LabServerTest, APausedRunSendsOneStateThenOnlyAComment) {
  const std::string id = start({{"scene", "minimal"}});
  // Read until the stream's first comment, which it sends after 2 s with nothing to say.
  const std::vector<std::string> blocks =
      stream_blocks(id, [](const std::string& block) { return block.starts_with(":"); });
  ASSERT_GE(blocks.size(), 2u);
  EXPECT_EQ(blocks.back(), ":");
  // The paused run at t = 0, said once: an unchanged state is not sent again.
  EXPECT_EQ(blocks.size(), 2u);
  EXPECT_TRUE(blocks.front().starts_with("event: state\n")) << blocks.front();
}

TEST_F(LabServerTest, StreamsAreToldWhenTheServerStops) {
  const std::string id = start({{"scene", "minimal"}});
  std::vector<std::string> names;
  std::thread reader([&] {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(20, 0);
    std::string buffer;
    c.Get(session(id, "/stream").c_str(), [&](const char* data, std::size_t n) {
      buffer.append(data, n);
      for (std::size_t end; (end = buffer.find("\n\n")) != std::string::npos;) {
        names.push_back(buffer.substr(7, buffer.find('\n') - 7));
        buffer.erase(0, end + 2);
      }
      return true;
    });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  server_->stop();
  reader.join();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "state");
  EXPECT_EQ(names.back(), "closed");
}

// A client that asks too fast is told to wait; the server goes on serving.
class RateLimitedServerTest : public LabServerTest {
 protected:
  RateLimitedServerTest() { requests_per_second_ = 2.0; }
};

TEST_F(RateLimitedServerTest, AClientAskingTooFastIsToldToWait) {
  int answered = 0;
  int refused = 0;
  for (int i = 0; i < 12; ++i) {
    const auto res = client_->Get("/api/lab");
    ASSERT_TRUE(res);
    if (res->status == 200) ++answered;
    if (res->status == 429) {
      ++refused;
      EXPECT_GE(std::stoi(res->get_header_value("Retry-After")), 1);
      EXPECT_NE(res->body.find("at most 2 a second"), std::string::npos) << res->body;
    }
  }
  // A burst of three seconds' worth, then one every half second.
  EXPECT_GE(answered, 6);
  EXPECT_LE(answered, 7);
  EXPECT_EQ(answered + refused, 12);
  // The page itself is not rationed.
  EXPECT_EQ(client_->Get("/")->status, 200);
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  EXPECT_EQ(client_->Get("/api/lab")->status, 200);
}

TEST_F(LabServerTest, OversizedHeadersAndBrokenBodiesCostTheirClientOnly) {
  // A header of 100 kB: refused, never read whole.
  const std::string big = send_raw(
      "GET /api/lab HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(100000, 'a') + "\r\n\r\n");
  EXPECT_EQ(big.find("HTTP/1.1 200"), std::string::npos) << big.substr(0, 200);
  // A body larger than 64 kB, and a chunked body whose chunk sizes lie.
  const std::string large = send_raw(
      "POST /api/sessions HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
      "Content-Length: 200000\r\n\r\n" +
      std::string(200000, '{'));
  EXPECT_EQ(large.find("HTTP/1.1 20"), std::string::npos) << large.substr(0, 200);
  const std::string chunked = send_raw(
      "POST /api/sessions HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n"
      "ffffffff\r\n{\"scene\"\r\nzz\r\n\r\n");
  EXPECT_EQ(chunked.find("HTTP/1.1 20"), std::string::npos) << chunked.substr(0, 200);
  // The server goes on.
  const auto res = client_->Get("/api/lab");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_NE(start({{"scene", "minimal"}}), "");
}

// Sessions nobody watches end after half a second.
class ForgetfulServerTest : public LabServerTest {
 protected:
  ForgetfulServerTest() { idle_seconds_ = 0.5; }
};

TEST_F(ForgetfulServerTest, ASessionNobodyWatchesEndsAndOneWatchedStays) {
  const std::string left = start({{"scene", "minimal"}});
  const std::string watched = start({{"scene", "minimal"}});
  std::atomic<bool> leave{false};
  std::thread viewer([&] {
    httplib::Client c("127.0.0.1", port_);
    c.Get(session(watched, "/stream").c_str(), [&](const char*, std::size_t) { return !leave; });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  // Any API request looks; the one left alone has ended, the one streamed goes on.
  EXPECT_EQ(client_->Get("/api/lab")->status, 200);
  EXPECT_EQ(server_->sessions(), 1);
  EXPECT_EQ(command(left, {{"action", "play"}})->status, 404);
  EXPECT_EQ(command(watched, {{"action", "play"}})->status, 200);
  leave = true;
  viewer.join();
}

// A closed tab's session leaves the class's table after half a second here (20 s by default),
// while a watched one stays; the closed one stays open in case its page comes back.
class ShortListServerTest : public LabServerTest {
 protected:
  ShortListServerTest() { listed_seconds_ = 0.5; }
};

TEST_F(ShortListServerTest, AClosedTabsSessionLeavesTheClassTable) {
  const std::string gone = start({{"scene", "minimal"}, {"name", "Gone"}});
  const std::string watched = start({{"scene", "minimal"}, {"name", "Here"}});
  const auto names = [&] {
    std::vector<std::string> out;
    const json table = json::parse(client_->Get("/api/class")->body);
    for (const json& row : table["sessions"]) out.push_back(row["name"].get<std::string>());
    return out;
  };
  EXPECT_EQ(names(), (std::vector<std::string>{"Gone", "Here"}));
  std::atomic<bool> leave{false};
  std::thread viewer([&] {
    httplib::Client c("127.0.0.1", port_);
    c.Get(session(watched, "/stream").c_str(), [&](const char*, std::size_t) { return !leave; });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  EXPECT_EQ(names(), (std::vector<std::string>{"Here"}));
  EXPECT_EQ(server_->sessions(), 2);
  // Its page comes back: a control, and it is listed again.
  EXPECT_EQ(command(gone, {{"action", "pause"}})->status, 200);
  EXPECT_EQ(names(), (std::vector<std::string>{"Gone", "Here"}));
  leave = true;
  viewer.join();
}

}  // namespace
}  // namespace fl::serve
