// The live rig in the server (docs/web-api.md, "The live rig"), end to end on a pseudo-terminal:
// a simulated run's Hall samples sent in the rig firmware's format at real speed (1 kHz), read by
// the server as `estimate --follow` reads a port, streamed to a page as `rig` events. The page's
// periods are those `estimate` finds in the recorded log, the log is what was sent, an unplugged
// board is said and its log kept; a page opens only a port the server listed, and a shared
// server lets no page open one.
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "api/api_contract.hpp"
#include "hall_log/hall_log.hpp"
#include "lab/live/live_run.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/request/session_request.hpp"
#include "serve/lab_server.hpp"
#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

class LiveRigTest : public test::TempFolderTest {
 protected:
  LiveRigTest() : TempFolderTest("live-rig") {}

  void SetUp() override {
    TempFolderTest::SetUp();
    const std::filesystem::path scenes =
        std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / "scenes";
    std::filesystem::create_directories(dir_ / "scenes");
    std::filesystem::copy_file(scenes / "paper-rig.yaml", dir_ / "scenes" / "paper-rig.yaml");
    write("web/index.html", "<!doctype html><title>frictionlab</title>");
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    ASSERT_GE(master_, 0);
    ASSERT_EQ(::grantpt(master_), 0);
    ASSERT_EQ(::unlockpt(master_), 0);
    port_name_ = ::ptsname(master_);
    options_.port = 0;
    options_.scenes_dir = (dir_ / "scenes").string();
    options_.web_dir = (dir_ / "web").string();
    options_.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
  }
  void TearDown() override {
    stop_reading_ = true;
    if (server_) server_->stop();
    if (serving_.joinable()) serving_.join();
    if (reading_.joinable()) reading_.join();
    if (master_ >= 0) ::close(master_);
    TempFolderTest::TearDown();
  }

  void serve() {
    server_ = std::make_unique<LabServer>(options_);
    port_ = server_->bind();
    serving_ = std::thread([this] { server_->listen(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(30, 0);
  }

  httplib::Result post(const std::string& path, const json& body) {
    return client_->Post(path.c_str(), body.dump(), "application/json");
  }

  // A page: a session of the paper's rig, whose stream's `rig` events are collected.
  void open_page() {
    const auto res = post("/api/sessions", {{"scene", "paper-rig"}});
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 201) << res->body;
    const json session = json::parse(res->body);
    const std::string id = session["id"];
    const std::string key = session["key"];
    reading_ = std::thread([this, id, key] {
      httplib::Client reader("127.0.0.1", port_);
      reader.set_read_timeout(60, 0);
      std::string buffer;
      reader.Get(("/api/sessions/" + id + "/stream?key=" + key).c_str(),
                 [&](const char* data, std::size_t length) {
                   buffer.append(data, length);
                   for (std::size_t end; (end = buffer.find("\n\n")) != std::string::npos;) {
                     const std::string block = buffer.substr(0, end);
                     buffer.erase(0, end + 2);
                     if (!block.starts_with("event: rig\n")) continue;
                     const std::lock_guard lock(mutex_);
                     rig_events_.push_back(json::parse(block.substr(block.find("data: ") + 6)));
                   }
                   return !stop_reading_;
                 });
    });
  }

  // Waits until a `rig` event says `state`; false after 10 s.
  bool wait_for_state(const std::string& state) {
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (Clock::now() < deadline) {
      {
        const std::lock_guard lock(mutex_);
        if (!rig_events_.empty() && rig_events_.back()["state"] == state) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  ServeOptions options_;
  int master_ = -1;
  std::string port_name_;
  std::unique_ptr<LabServer> server_;
  std::thread serving_;
  int port_ = 0;
  std::unique_ptr<httplib::Client> client_;
  std::thread reading_;
  std::atomic<bool> stop_reading_{false};
  std::mutex mutex_;
  std::vector<json> rig_events_;
};

TEST_F(LiveRigTest, ThePagesPeriodsAreWhatEstimateFindsInTheRecordedLog) {
  // A simulated run of the paper's rig with a rigid-foam plate (T = 0.30 s: enough periods in a
  // few seconds), its Hall samples as the firmware's 1 kHz lines.
  const PreparedSession sim =
      prepare_session({"paper-rig", {"friction.mu_k=rigid-foam", "world.duration=3.5s"}},
                      options_.scenes_dir, options_.asset_dir);
  LiveRun run(sim.rig, sim.output);
  run.advance_to(1e9);
  const double truth = run.summary().period_trajectory.value();
  std::vector<std::pair<long, std::string>> samples;  // t_us, line
  {
    std::istringstream in(run.file("hall.csv").value());
    std::string line;
    std::getline(in, line);  // t_us,adc
    while (std::getline(in, line)) samples.push_back({std::stol(line), line});
  }
  ASSERT_GT(samples.size(), 3000u);

  options_.serial_port = port_name_;
  options_.record_dir = (dir_ / "record").string();
  std::filesystem::create_directories(options_.record_dir);
  serve();
  open_page();
  ASSERT_TRUE(wait_for_state("waiting"));

  std::string sent;
  const auto send = [&](const std::string& text) {
    sent += text;
    ASSERT_EQ(::write(master_, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  };
  send("# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 raw_every=1\r\n");
  send("t_us,adc\r\n");
  const auto t0 = Clock::now();
  std::size_t next = 0;
  while (next < samples.size()) {
    const auto now = Clock::now();
    std::string chunk;
    while (next < samples.size() && t0 + std::chrono::microseconds(samples[next].first) <= now)
      chunk += samples[next++].second + "\r\n";
    if (!chunk.empty()) send(chunk);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_NEAR(std::chrono::duration<double>(Clock::now() - t0).count(), samples.back().first * 1e-6,
              0.2);  // real speed
  // Periods came while the samples did, before the board was unplugged.
  std::size_t live_periods = 0;
  {
    const std::lock_guard lock(mutex_);
    for (const json& e : rig_events_) live_periods += e["periods"].size();
  }
  EXPECT_GE(live_periods, 6u);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::close(master_);
  master_ = -1;
  ASSERT_TRUE(wait_for_state("unplugged"));

  std::vector<json> events;
  {
    const std::lock_guard lock(mutex_);
    events = rig_events_;
  }
  // Each event is what the web API declares (api/api_fields.hpp), and the port's status too.
  for (const json& e : events)
    EXPECT_EQ(api::contract_problems(e, "LiveRigEvent", "rig").size(), 0u) << e;
  const auto status = client_->Get("/api/rig");
  ASSERT_TRUE(status);
  EXPECT_EQ(api::contract_problems(json::parse(status->body), "LiveRig", "status").size(), 0u)
      << status->body;
  const json& last = events.back();
  EXPECT_NE(last["message"].get<std::string>().find("kept"), std::string::npos) << last;
  EXPECT_EQ(last["lines"], static_cast<int>(samples.size()) + 2);
  // The log, downloaded and as recorded, is what was sent.
  const auto log = client_->Get("/api/rig/log");
  ASSERT_TRUE(log);
  ASSERT_EQ(log->status, 200);
  EXPECT_EQ(log->body, sent);
  const std::optional<std::string> recorded = server_->rig_record_path();
  ASSERT_TRUE(recorded);
  EXPECT_EQ(test::read_text(*recorded), sent);

  // `estimate --spacing L` on the recorded log: the page's periods are its periods, each exactly.
  LogSetUp set_up;
  set_up.spacing = last["spacing"];
  const LogEstimate estimate = estimate_log(read_hall_log(*recorded), set_up, false);
  std::vector<json> page;
  for (const json& e : events)
    for (const json& p : e["periods"]) page.push_back(p);
  ASSERT_GE(page.size(), 6u);
  ASSERT_GE(estimate.periods.size(), page.size());
  EXPECT_LE(estimate.periods.size(), page.size() + 1);  // the end completes one more at most
  for (std::size_t i = 0; i < page.size(); ++i) {
    const EstimatedPeriod& p = estimate.periods[i];
    EXPECT_EQ(page[i], json::array({p.start, p.end, p.period, p.status == fl_estimator::kAccepted}))
        << i;
  }
  // And they time the simulated plate.
  ASSERT_FALSE(last["estimate"].is_null());
  EXPECT_NEAR(last["estimate"]["period"].get<double>(), truth, 5e-4 * truth);
  EXPECT_EQ(last["geometry"], "one-pulse");
}

TEST_F(LiveRigTest, APageOpensOnlyAPortTheServerListedAndASharedServerNone) {
  // A device folder with an Uno (and its by-id name), a built-in serial port, and a file.
  options_.device_dir = (dir_ / "dev").string();
  const std::string acm = write("dev/ttyACM0", "");
  const std::string by_id = write("dev/serial/by-id/usb-Arduino_Uno-if00", "");
  write("dev/ttyS0", "");
  write("dev/null", "");
  serve();
  const json rig = json::parse(client_->Get("/api/rig")->body);
  EXPECT_EQ(rig["ports"], json::array({by_id, acm}));
  EXPECT_EQ(rig["may_choose"], true);
  EXPECT_EQ(rig["state"], "closed");
  EXPECT_EQ(rig["port"], nullptr);
  EXPECT_EQ(client_->Get("/api/rig/log")->status, 404);
  // Nothing a page sends is taken as a path.
  for (const std::string port : {"/etc/passwd", "/dev/ttyS0", "../dev/ttyACM0", ""}) {
    const auto res = post("/api/rig", {{"port", port}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << port;
    EXPECT_NE(res->body.find("GET /api/rig's ports"), std::string::npos) << res->body;
  }
  for (const json& bad : {json{{"port", 3}}, json{{"action", "open"}}, json::array()}) {
    const auto res = post("/api/rig", bad);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad;
  }
  // A listed port that is not a terminal: opened, and the page is told why it gives nothing.
  const auto opened = post("/api/rig", {{"port", acm}});
  ASSERT_TRUE(opened);
  ASSERT_EQ(opened->status, 200);
  const json failed = json::parse(opened->body);
  EXPECT_EQ(failed["state"], "failed");
  EXPECT_NE(failed["message"].get<std::string>().find("expected a serial port"), std::string::npos)
      << failed;
  EXPECT_EQ(json::parse(post("/api/rig", {{"action", "close"}})->body)["port"], acm);

  // A shared server (another host than this machine's, no --serial): no page opens a port.
  server_->stop();
  serving_.join();
  options_.pages_choose_port = false;
  serve();
  const json shared = json::parse(client_->Get("/api/rig")->body);
  EXPECT_EQ(shared["ports"], json::array());
  EXPECT_EQ(shared["may_choose"], false);
  const auto refused = post("/api/rig", {{"port", acm}});
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 403);
  EXPECT_NE(refused->body.find("--serial"), std::string::npos);
  // Nor closes the one --serial opened: the class's rig is not a student's to stop.
  const auto closing = post("/api/rig", {{"action", "close"}});
  ASSERT_TRUE(closing);
  EXPECT_EQ(closing->status, 403);
}

}  // namespace
}  // namespace fl::serve
