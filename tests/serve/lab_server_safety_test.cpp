// The classroom's safety (docs/classroom.md, "Students on the same network"): a session obeys only
// the page holding its key, the class's table shows no key, no body grows the server however it
// is sent, the scenes folder never reads what lies outside it, and no error names a path of the
// server's machine. Behaviour only: nothing here is timed.
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab_server_fixture.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr auto npos = std::string::npos;

// A chunk's size as chunked encoding writes it: hexadecimal.
std::string hex(std::size_t size) {
  std::ostringstream out;
  out << std::hex << size;
  return out.str();
}

// The JSON body of a raw answer (after its head), or null.
json body_of(const std::string& answer) {
  const auto start = answer.find("\r\n\r\n");
  if (start == npos) return nullptr;
  return json::parse(answer.substr(start + 4), nullptr, /*allow_exceptions=*/false);
}

TEST_F(LabServerTest, AnotherClientWithTheIdButNotTheKeyCannotControlTheSession) {
  const std::string mine = start({{"scene", "minimal"}});
  const std::string theirs = start({{"scene", "minimal"}});
  ASSERT_FALSE(mine.empty());
  ASSERT_FALSE(theirs.empty());
  // The key is a secret of its own, not the id.
  EXPECT_EQ(keys_[mine].size(), 32u) << keys_[mine];
  EXPECT_EQ(keys_[mine].find_first_not_of("0123456789abcdef"), npos) << keys_[mine];
  EXPECT_NE(keys_[mine], keys_[theirs]);
  EXPECT_EQ(keys_[mine].find(mine), npos);
  ASSERT_EQ(command(mine, {{"action", "step"}})->status, 200);

  // Another page knows the id (the class's table lists it): without the key, with its own key,
  // or with a guess, it neither plays, resets, slows, streams, downloads nor ends the session.
  const std::string path = "/api/sessions/" + mine;
  const std::vector<httplib::Headers> strangers = {
      {}, {{"X-Session-Key", keys_[theirs]}}, {{"X-Session-Key", std::string(32, '0')}}};
  for (const httplib::Headers& headers : strangers) {
    for (const json& command :
         {json{{"action", "play"}}, json{{"action", "reset"}}, json{{"speed", 0.0625}}}) {
      const auto res =
          client_->Post((path + "/control").c_str(), headers, command.dump(), "application/json");
      ASSERT_TRUE(res);
      EXPECT_EQ(res->status, 403) << command.dump();
      EXPECT_NE(res->body.find("controlled only by the page that opened it"), npos) << res->body;
    }
    const auto ended = client_->Delete(path.c_str(), headers);
    ASSERT_TRUE(ended);
    EXPECT_EQ(ended->status, 403) << ended->body;
    const auto file = client_->Get((path + "/files/summary.json").c_str(), headers);
    ASSERT_TRUE(file);
    EXPECT_EQ(file->status, 403) << file->body;
    // A stream would advance the run: refused before its first event.
    int stream_status = 0;
    client_->Get((path + "/stream").c_str(), headers,
                 [&](const httplib::Response& r) {
                   stream_status = r.status;
                   return r.status != 200;
                 },
                 [](const char*, std::size_t) { return true; });
    EXPECT_EQ(stream_status, 403);
  }
  // A control takes the key in its header only: a download's link, which carries the key in its
  // address, shared by its student, controls nothing.
  for (const std::string& key : {keys_[theirs], keys_[mine]}) {
    const auto linked = client_->Post((path + "/control?key=" + key).c_str(),
                                      json{{"action", "reset"}}.dump(), "application/json");
    ASSERT_TRUE(linked);
    EXPECT_EQ(linked->status, 403) << linked->body;
    const auto unlinked = client_->Delete((path + "?key=" + key).c_str());
    ASSERT_TRUE(unlinked);
    EXPECT_EQ(unlinked->status, 403) << unlinked->body;
  }

  // The session goes on as its page left it: stepped once, not reset, not slowed, not ended.
  EXPECT_EQ(server_->sessions(), 2);
  std::string buffer;
  json first;
  httplib::Client page("127.0.0.1", port_);
  page.Get(session(mine, "/stream").c_str(), [&](const char* data, std::size_t n) {
    buffer.append(data, n);
    const auto end = buffer.find("\n\n");
    if (end == npos) return true;
    const auto at = buffer.find("data: ") + 6;
    first = json::parse(buffer.substr(at, end - at));
    return false;
  });
  ASSERT_TRUE(first.is_object()) << buffer;
  EXPECT_NEAR(first["t"].get<double>(), 1.0 / 30, 1e-3 + 1e-12);
  EXPECT_EQ(first["speed"], 1.0);
  const auto own = client_->Delete(path.c_str(), {{"X-Session-Key", keys_[mine]}});
  ASSERT_TRUE(own);
  EXPECT_EQ(own->status, 200);
  EXPECT_EQ(server_->sessions(), 1);
}

TEST_F(LabServerTest, TheClassTableListsEverySessionButNoKey) {
  const std::string ada = start({{"scene", "minimal"}, {"name", "Ada"}});
  const std::string bob = start({{"scene", "paper-rig"}, {"name", "Bob"}});
  // The teacher's table needs no key: it controls nothing.
  const auto table = client_->Get("/api/class");
  ASSERT_TRUE(table);
  ASSERT_EQ(table->status, 200);
  const json rows = json::parse(table->body)["sessions"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["session"], ada);
  EXPECT_EQ(rows[1]["session"], bob);
  for (const json& row : rows) EXPECT_FALSE(row.contains("key")) << row.dump();
  const auto csv = client_->Get("/api/class.csv");
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200);
  for (const std::string& id : {ada, bob}) {
    EXPECT_EQ(table->body.find(keys_[id]), npos) << table->body;
    EXPECT_EQ(csv->body.find(keys_[id]), npos) << csv->body;
    EXPECT_NE(csv->body.find(id), npos) << csv->body;
  }
}

TEST_F(LabServerTest, ABodyOverTheLimitIsRefused413HoweverItIsSentAndTheServerGoesOn) {
  const std::string head =
      "POST /api/sessions HTTP/1.1\r\nHost: lab\r\nContent-Type: application/json\r\n";
  const std::string chunk = "4000\r\n" + std::string(0x4000, ' ') + "\r\n";  // 16 KiB
  // A chunked body of 1 MiB from a client that keeps its connection open: half of the limit
  // sent, another client is served meanwhile; then the rest, refused.
  RawConnection chunked(port_);
  ASSERT_TRUE(chunked.connected());
  ASSERT_TRUE(chunked.send(head + "Transfer-Encoding: chunked\r\n\r\n" + chunk + chunk));
  const auto other = client_->Get("/api/lab");
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 200);
  for (int i = 2; i < 64 && chunked.send(chunk); ++i) {
  }
  const std::string refused = chunked.answer();
  EXPECT_EQ(refused.rfind("HTTP/1.1 413", 0), 0u) << refused.substr(0, 200);
  const json said = body_of(refused);
  ASSERT_TRUE(said.is_object()) << refused.substr(0, 400);
  EXPECT_NE(said["error"].get<std::string>().find("larger than 64 KiB"), npos) << said.dump();

  // Sent without a length (until the client stops sending), and with a length over the limit.
  RawConnection unmeasured(port_);
  ASSERT_TRUE(unmeasured.connected());
  unmeasured.send(head + "\r\n" + std::string(200 * 1024, ' '));
  const std::string no_length = unmeasured.answer();
  EXPECT_EQ(no_length.rfind("HTTP/1.1 413", 0), 0u) << no_length.substr(0, 200);
  EXPECT_TRUE(body_of(no_length).contains("error")) << no_length.substr(0, 400);
  RawConnection measured(port_);
  ASSERT_TRUE(measured.connected());
  measured.send(head + "Content-Length: 200000\r\n\r\n" + std::string(200000, ' '));
  const std::string long_length = measured.answer();
  EXPECT_EQ(long_length.rfind("HTTP/1.1 413", 0), 0u) << long_length.substr(0, 200);
  EXPECT_TRUE(body_of(long_length).contains("error")) << long_length.substr(0, 400);

  // A chunked body within the limit is a body like any other.
  const std::string request = json{{"scene", "minimal"}}.dump();
  RawConnection small(port_);
  ASSERT_TRUE(small.connected());
  small.send(head + "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n" +
             hex(request.size()) + "\r\n" + request + "\r\n0\r\n\r\n");
  const std::string taken = small.answer();
  EXPECT_EQ(taken.rfind("HTTP/1.1 201", 0), 0u) << taken.substr(0, 400);

  // Nor does a head without end grow it: 431, and the server goes on.
  RawConnection headers(port_);
  ASSERT_TRUE(headers.connected());
  std::string flood = "GET /api/lab HTTP/1.1\r\nHost: lab\r\n";
  for (int i = 0; i < 64; ++i) flood += "X-Padding: " + std::string(4000, 'a') + "\r\n";
  headers.send(flood);
  const std::string too_long = headers.answer();
  EXPECT_EQ(too_long.rfind("HTTP/1.1 431", 0), 0u) << too_long.substr(0, 200);
  const auto after = client_->Get("/api/lab");
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200);
  EXPECT_EQ(server_->sessions(), 1);
}

TEST_F(LabServerTest, AScenesLinkOutsideTheFolderIsRefusedAsIfAbsent) {
  const std::string secret =
      write("outside/notes.yaml", "# TOP SECRET: the exam's answers\nformat: 1\nanswer: hunter2\n");
  fs::create_symlink(secret, dir_ / "scenes" / "notes.yaml");
  fs::create_symlink("/etc/passwd", dir_ / "scenes" / "passwd.yaml");
  // A link that stays inside the folder is a scene like any other.
  fs::create_symlink("minimal.yaml", dir_ / "scenes" / "alias.yaml");

  const auto lab = client_->Get("/api/lab");
  ASSERT_TRUE(lab);
  const json offered = json::parse(lab->body);
  std::vector<std::string> names;
  for (const json& scene : offered["scenes"]) names.push_back(scene["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"alias", "minimal", "paper-rig"}));
  EXPECT_EQ(lab->body.find("TOP SECRET"), npos) << lab->body;

  for (const std::string scene : {"notes", "passwd"}) {
    const auto res = post("/api/sessions", {{"scene", scene}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << res->body;
    const json body = json::parse(res->body);
    ASSERT_EQ(body["problems"].size(), 1u) << res->body;
    EXPECT_EQ(body["problems"][0]["field"], "scene");
    // Named as any name not offered, with those that are.
    const std::string message = body["problems"][0]["message"];
    EXPECT_NE(message.find("found \"" + scene + "\""), npos) << message;
    EXPECT_NE(message.find("alias, minimal, paper-rig"), npos) << message;
    for (const std::string& told :
         {secret, std::string("outside"), std::string("TOP SECRET"), std::string("hunter2"),
          std::string("/etc/passwd"), std::string("root:"), std::string("/bin/")})
      EXPECT_EQ(res->body.find(told), npos) << told << " in " << res->body;
  }
  EXPECT_EQ(post("/api/sessions", {{"scene", "alias"}})->status, 201);
}

TEST_F(LabServerTest, ErrorBodiesNameNoPathOfTheServersMachine) {
  write("scenes/broken.yaml", "# a scene with a typo\nformat: 1\nrollers:\n  spacng: 89 mm\n");
  const std::string id = start({{"scene", "minimal"}});
  std::vector<std::pair<std::string, httplib::Result>> answers;
  answers.emplace_back("a broken scene", post("/api/sessions", {{"scene", "broken"}}));
  answers.emplace_back("no such scene", post("/api/sessions", {{"scene", "nothing"}}));
  answers.emplace_back("a bad set entry",
                       post("/api/sessions", {{"scene", "minimal"}, {"set", {"rollers.x=1"}}}));
  answers.emplace_back("not JSON", client_->Post("/api/sessions", "garbage", "application/json"));
  answers.emplace_back("no such session",
                       post("/api/sessions/0123456789abcdef/control", {{"action", "play"}}));
  answers.emplace_back("no key", post("/api/sessions/" + id + "/control", {{"action", "play"}}));
  answers.emplace_back("no file yet", client_->Get(session(id, "/files/summary.json").c_str()));
  answers.emplace_back("a large body",
                       client_->Post("/api/sessions", std::string(100000, ' '), "text/plain"));
  // The scene's problem names the scene's file and the key, by name only.
  ASSERT_TRUE(answers[0].second) << httplib::to_string(answers[0].second.error());
  EXPECT_EQ(answers[0].second->status, 400);
  EXPECT_NE(answers[0].second->body.find("broken.yaml"), npos) << answers[0].second->body;
  EXPECT_NE(answers[0].second->body.find("spacng"), npos) << answers[0].second->body;

  std::vector<std::string> places{
      dir_.string(), fs::canonical(dir_).string(), fs::temp_directory_path().string(),
      fs::absolute(FRICTIONLAB_TEST_ASSET_DIR).string(), fs::current_path().string()};
  for (const auto& [what, res] : answers) {
    ASSERT_TRUE(res) << what;
    EXPECT_GE(res->status, 400) << what;
    EXPECT_TRUE(json::parse(res->body).contains("error")) << what << ": " << res->body;
    for (const std::string& place : places)
      EXPECT_EQ(res->body.find(place), npos) << what << " names " << place << ": " << res->body;
  }
}

}  // namespace
}  // namespace fl::serve
