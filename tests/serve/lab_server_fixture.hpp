// The server in-process on an ephemeral port, and a real HTTP client beside it: the fixture of the
// server's tests (lab_server_test.cpp, lab_server_safety_test.cpp).
#pragma once

#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/lab_server.hpp"
#include "support/temp_folder.hpp"

namespace fl::serve {

// A connection of the test's own to the server, for bytes no HTTP client sends.
class RawConnection {
 public:
  explicit RawConnection(int port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  }
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;
  ~RawConnection() { ::close(fd_); }

  bool connected() const { return connected_; }
  // Whether every byte went (false once the server closed the connection).
  bool send(const std::string& bytes) {
    for (std::size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return false;
      sent += static_cast<std::size_t>(n);
    }
    return true;
  }
  // What the server answered, until it closed the connection (a minute at most). The test's
  // side stays open: a server answers no client that has gone, and a half-closed one may look so.
  std::string answer() {
    timeval patience{60, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &patience, sizeof patience);
    std::string out;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd_, buffer, sizeof buffer, 0)) > 0;)
      out.append(buffer, static_cast<std::size_t>(n));
    return out;
  }

 private:
  int fd_;
  bool connected_ = false;
};

class LabServerTest : public test::TempFolderTest {
 protected:
  using json = nlohmann::json;

  LabServerTest() : TempFolderTest("lab-server") {}

  void SetUp() override {
    TempFolderTest::SetUp();
    const std::filesystem::path scenes =
        std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / "scenes";
    std::filesystem::create_directories(dir_ / "scenes");
    for (const char* name : {"minimal.yaml", "paper-rig.yaml"})
      std::filesystem::copy_file(scenes / name, dir_ / "scenes" / name);
    write("web/index.html", "<!doctype html><title>frictionlab</title>");
    ServeOptions options;
    options.host = "127.0.0.1";
    options.port = 0;
    options.scenes_dir = (dir_ / "scenes").string();
    options.web_dir = (dir_ / "web").string();
    options.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
    options.version = "frictionlab test";
    options.max_sessions = max_sessions_;
    options.token = token_;
    options.requests_per_second = requests_per_second_;
    options.idle_seconds = idle_seconds_;
    options.listed_seconds = listed_seconds_;
    server_ = std::make_unique<LabServer>(options);
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->listen(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(30, 0);
  }
  void TearDown() override {
    server_->stop();
    thread_.join();
    TempFolderTest::TearDown();
  }

  httplib::Result post(const std::string& path, const json& body) {
    return client_->Post(path.c_str(), body.dump(), "application/json");
  }
  // A session's id (its key kept in keys_), or fails the test.
  std::string start(const json& request, const std::string& path = "/api/sessions") {
    const auto res = post(path, request);
    EXPECT_TRUE(res);
    if (!res) return "";
    EXPECT_EQ(res->status, 201) << res->body;
    const json body = json::parse(res->body);
    const auto id = body.find("id");
    const auto key = body.find("key");
    if (id == body.end() || !id->is_string() || key == body.end() || !key->is_string()) {
      ADD_FAILURE() << "no id and key in " << res->body;
      return "";
    }
    keys_[*id] = *key;
    return *id;
  }
  // A session's address with its key (?key=), as its page opens a stream or a download.
  std::string session(const std::string& id, const std::string& rest = "") const {
    return "/api/sessions/" + id + rest + "?key=" + key_of(id);
  }
  // A control as its page sends it: the key in the header X-Session-Key.
  httplib::Result command(const std::string& id, const json& body) {
    return client_->Post(("/api/sessions/" + id + "/control").c_str(),
                         {{"X-Session-Key", key_of(id)}}, body.dump(), "application/json");
  }
  // Ends a session as its page does; `query` for the server's token ("?token=...").
  httplib::Result end(const std::string& id, const std::string& query = "") {
    return client_->Delete(("/api/sessions/" + id + query).c_str(),
                           {{"X-Session-Key", key_of(id)}});
  }
  std::string key_of(const std::string& id) const {
    const auto key = keys_.find(id);
    return key == keys_.end() ? "" : key->second;
  }
  // Bytes on a connection of their own, as no HTTP client would send them; what the server
  // answered (until it closed the connection), or nothing when not waited for.
  std::string send_raw(const std::string& bytes, bool wait_for_answer = true) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port_));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    (void)::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    std::string answer;
    if (wait_for_answer) {
      ::shutdown(fd, SHUT_WR);
      char buffer[4096];
      for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
        answer.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return answer;
  }
  // Reads the stream until `done`: every event's name and data.
  // The session's stream, block by block (an event, or a comment: the stream with nothing to say),
  // each without its blank line, up to the first block `last` holds for.
  std::vector<std::string> stream_blocks(const std::string& id,
                                         const std::function<bool(const std::string&)>& last) {
    std::vector<std::string> blocks;
    std::string buffer;
    httplib::Client reader("127.0.0.1", port_);
    reader.set_read_timeout(60, 0);
    reader.Get(session(id, "/stream").c_str(), [&](const char* data, std::size_t length) {
      buffer.append(data, length);
      for (std::size_t end; (end = buffer.find("\n\n")) != std::string::npos;) {
        blocks.push_back(buffer.substr(0, end));
        buffer.erase(0, end + 2);
        if (last(blocks.back())) return false;
      }
      return true;
    });
    return blocks;
  }

  // The session's events, name and data, up to its `done`.
  std::vector<std::pair<std::string, json>> stream_to_done(const std::string& id) {
    std::vector<std::pair<std::string, json>> events;
    for (const std::string& block :
         stream_blocks(id, [](const std::string& b) { return b.starts_with("event: done\n"); })) {
      if (block.starts_with(":")) continue;  // a comment
      const auto name_end = block.find('\n');
      events.emplace_back(block.substr(7, name_end - 7), json::parse(block.substr(name_end + 7)));
    }
    return events;
  }

  std::map<std::string, std::string> keys_;  // each session's key, by id
  int max_sessions_ = 30;
  std::string token_;
  double requests_per_second_ = 1000.0;
  double idle_seconds_ = 600.0;
  double listed_seconds_ = 20.0;
  std::unique_ptr<LabServer> server_;
  std::thread thread_;
  int port_ = 0;
  std::unique_ptr<httplib::Client> client_;
};

}  // namespace fl::serve
