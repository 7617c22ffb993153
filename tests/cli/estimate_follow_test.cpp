// frictionlab estimate --follow PORT, end to end on a pseudo-terminal: a simulated run's samples
// sent in the rig firmware's output format at real speed (1 kHz), each period printed as it
// comes, the raw log written as received, Ctrl-C ending it with the summary, whose T is the
// run's and the same as `estimate` gives on the raw log.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"

namespace fl {
namespace {

using Clock = std::chrono::steady_clock;
const std::string kExe = FRICTIONLAB_EXE;
const std::string kSource = FRICTIONLAB_TEST_SOURCE_DIR;

class Follow : public test::TempFolderTest {
 protected:
  Follow() : TempFolderTest("fl-follow") {}
  void SetUp() override {
    TempFolderTest::SetUp();
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    ASSERT_GE(master_, 0);
    ASSERT_EQ(::grantpt(master_), 0);
    ASSERT_EQ(::unlockpt(master_), 0);
    port_ = ::ptsname(master_);
  }
  void TearDown() override {
    if (child_ > 0) {
      ::kill(child_, SIGKILL);
      ::waitpid(child_, nullptr, 0);
    }
    if (out_ >= 0) ::close(out_);
    if (master_ >= 0) ::close(master_);
    TempFolderTest::TearDown();
  }

  // Starts `frictionlab estimate --follow PORT ARGS`, its stdout on a pipe, stderr to a file.
  void start(const std::vector<std::string>& args) {
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    child_ = ::fork();
    ASSERT_GE(child_, 0);
    if (child_ == 0) {
      ::dup2(pipe_fds[1], 1);
      const int err = ::open((dir_ / "err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(err, 2);
      ::close(pipe_fds[0]);
      std::vector<std::string> all = {kExe, "estimate", "--follow", port_};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (std::string& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(kExe.c_str(), argv.data());
      ::_exit(127);
    }
    ::close(pipe_fds[1]);
    out_ = pipe_fds[0];
    ::fcntl(out_, F_SETFL, O_NONBLOCK);
  }

  // What the child printed since the last call, each complete line with when it was read.
  void collect(int wait_ms = 0) {
    pollfd p{out_, POLLIN, 0};
    if (::poll(&p, 1, wait_ms) <= 0) return;
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(out_, buffer, sizeof buffer)) > 0) {
      partial_.append(buffer, static_cast<std::size_t>(n));
      for (std::size_t end; (end = partial_.find('\n')) != std::string::npos;) {
        lines_.push_back({partial_.substr(0, end), Clock::now()});
        partial_.erase(0, end + 1);
      }
    }
    if (n == 0) closed_ = true;
  }

  int wait_exit() {
    const auto deadline = Clock::now() + std::chrono::seconds(20);
    int status = 0;
    while (Clock::now() < deadline) {
      collect(50);
      const pid_t done = ::waitpid(child_, &status, WNOHANG);
      if (done == child_) {
        child_ = -1;
        while (!closed_) collect(50);
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
    }
    return -1;
  }

  bool printed(const std::string& start) const {
    for (const auto& [line, when] : lines_)
      if (line.rfind(start, 0) == 0) return true;
    return false;
  }

  std::string all_output() const {
    std::string out;
    for (const auto& [line, when] : lines_) out += line + "\n";
    return out;
  }

  std::string port_;
  int master_ = -1;
  int out_ = -1;
  pid_t child_ = -1;
  std::string partial_;
  bool closed_ = false;
  std::vector<std::pair<std::string, Clock::time_point>> lines_;
};

TEST_F(Follow, PeriodsAsTheyComeTheRawLogAndTheSummaryAtCtrlC) {
  // A simulated run of the paper's rig with a rigid-foam plate (T = 0.30 s: enough periods in
  // a few seconds), sampled at the firmware's 1 kHz.
  const std::string run = (dir_ / "run").string();
  const test::CommandResult sim =
      test::run_command(kExe + " run " + kSource + "/scenes/paper-rig.yaml --set " +
                        "friction.mu_k=rigid-foam --duration 3.5s --out " + run);
  ASSERT_EQ(sim.status, 0) << sim.err;
  const double truth =
      nlohmann::json::parse(test::read_text(run + "/summary.json"))["period_trajectory_s"];
  std::vector<std::pair<long, std::string>> samples;  // t_us, line
  {
    std::istringstream in(test::read_text(run + "/hall.csv"));
    std::string line;
    std::getline(in, line);  // t_us,adc
    while (std::getline(in, line)) samples.push_back({std::stol(line), line});
  }
  ASSERT_GT(samples.size(), 3000u);

  const std::string raw = (dir_ / "raw.csv").string();
  start({"--log", raw});
  // The port is set up when the command says it follows it.
  const auto ready = Clock::now() + std::chrono::seconds(10);
  while (lines_.empty() && Clock::now() < ready) collect(50);
  ASSERT_TRUE(printed("frictionlab estimate --follow " + port_)) << all_output();

  // The firmware's output: its banner, the header, then each sample when it is taken.
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
    collect(0);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto fed = Clock::now();
  const double feed_s = std::chrono::duration<double>(fed - t0).count();
  EXPECT_NEAR(feed_s, samples.back().first * 1e-6, 0.2);  // real speed
  collect(300);
  ASSERT_EQ(::kill(child_, SIGINT), 0);
  const int status = wait_exit();
  const std::string err = test::read_text(dir_ / "err");
  ASSERT_EQ(status, 0) << all_output() << err;

  // Live: the signal, the geometry and the periods came before the end of the samples.
  int periods = 0;
  for (const auto& [line, when] : lines_) {
    if (line.rfind("  period ", 0) == 0 && line.find(" s accepted") != std::string::npos) {
      ++periods;
      if (periods == 1) {
        EXPECT_LT(when, fed) << line;
      }
    }
  }
  EXPECT_GE(periods, 6) << all_output();
  EXPECT_TRUE(printed("  signal learned")) << all_output();
  EXPECT_TRUE(printed("  geometry              one pulse per period")) << all_output();
  EXPECT_TRUE(printed("  stopped")) << all_output();
  // The raw log is what was sent.
  EXPECT_EQ(test::read_text(raw), sent);
  // The summary: the run's period, and what `estimate` gives on the raw log.
  std::string summary_t;
  for (const auto& [line, when] : lines_)
    if (line.rfind("  period T", 0) == 0) summary_t = line;
  ASSERT_FALSE(summary_t.empty()) << all_output();
  const double t = std::stod(summary_t.substr(summary_t.find_first_of("0123456789")));
  EXPECT_NEAR(t, truth, 5e-4 * truth);
  const test::CommandResult again = test::run_command(kExe + " estimate " + raw);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find(summary_t), std::string::npos) << again.out << "\n" << summary_t;
}

TEST_F(Follow, APortThatIsNotThereOrSilentIsALocatedError) {
  const test::CommandResult missing =
      test::run_command(kExe + " estimate --follow /dev/ttyNOSUCH0");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(
      missing.err.rfind("/dev/ttyNOSUCH0: error: no such serial port (is the board plugged in?", 0),
      0u)
      << missing.err;
  const test::CommandResult file =
      test::run_command(kExe + " estimate --follow " + kSource + "/README.md");
  EXPECT_EQ(file.status, 2);
  EXPECT_NE(file.err.find("expected a serial port"), std::string::npos) << file.err;
  start({"--duration", "1s"});
  EXPECT_EQ(wait_exit(), 2);
  const std::string err = test::read_text(dir_ / "err");
  EXPECT_EQ(err.rfind(port_ + ": error: nothing came from the port in 1.", 0), 0u) << err;
}

}  // namespace
}  // namespace fl
