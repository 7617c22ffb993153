// frictionlab run's progress line: on a terminal, a run past 3 s of wall time says how far it is
// ("run: t = X of D s (P %)", rewritten in place); on a pipe it says nothing, however long it
// runs. Each run is a long minimal-scene run stopped with SIGINT once the test has what it needs.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"

namespace fl {
namespace {

using Clock = std::chrono::steady_clock;
const std::string kExe = FRICTIONLAB_EXE;
const std::string kScene = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
constexpr double kDurationS = 1e6;  // far longer than any test waits: every run here is stopped

// Starts `frictionlab run minimal.yaml --duration 1e6s` with stdout to `out_path` and stderr to
// `stderr_fd`; returns the child's pid.
pid_t start_run(const std::filesystem::path& out_path, int stderr_fd) {
  const pid_t child = ::fork();
  if (child == 0) {
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(stderr_fd, 2);
    std::vector<std::string> all = {kExe, "run", kScene, "--duration", "1000000s"};
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(kExe.c_str(), argv.data());
    ::_exit(127);
  }
  return child;
}

int stop_and_wait(pid_t child) {
  ::kill(child, SIGINT);
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// The wall time the run's own summary reports ("... simulated in W s: ..."), or -1.
double wall_seconds(const std::string& summary) {
  const std::size_t at = summary.find("simulated in ");
  return at == std::string::npos ? -1.0 : std::stod(summary.substr(at + 13));
}

// A progress update as the terminal shows it: "\r\033[Krun: t = T of D s (P %)".
struct Update {
  double t = 0.0, duration = 0.0;
  int percent = -1;
};

// Every complete update in what the terminal showed.
std::vector<Update> updates(const std::string& shown) {
  const std::string start = "\r\033[Krun: t = ";
  std::vector<Update> out;
  for (std::size_t at = shown.find(start); at != std::string::npos;
       at = shown.find(start, at + 1)) {
    Update u;
    char close = 0;
    const std::string rest = shown.substr(at + start.size(), 64);
    if (std::sscanf(rest.c_str(), "%lf of %lf s (%d %%%c", &u.t, &u.duration, &u.percent, &close) ==
            4 &&
        close == ')')
      out.push_back(u);
  }
  return out;
}

class RunProgress : public test::TempFolderTest {
 protected:
  RunProgress() : TempFolderTest("fl-progress") {}
  void TearDown() override {
    if (child_ > 0) {
      ::kill(child_, SIGKILL);
      ::waitpid(child_, nullptr, 0);
    }
    TempFolderTest::TearDown();
  }
  pid_t child_ = -1;
};

TEST_F(RunProgress, OnATerminalARunPastThreeSecondsSaysHowFarItIs) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(::grantpt(master), 0);
  ASSERT_EQ(::unlockpt(master), 0);
  const int terminal = ::open(::ptsname(master), O_RDWR | O_NOCTTY);
  ASSERT_GE(terminal, 0);
  const auto started = Clock::now();
  child_ = start_run(dir_ / "out", terminal);
  ::close(terminal);

  // Read the terminal until two progress updates have come (or 60 s, for a slow build).
  std::string seen;
  std::vector<Update> shown;
  std::chrono::duration<double> first_after{0.0};
  while (shown.size() < 2 && Clock::now() - started < std::chrono::seconds(60)) {
    pollfd p{master, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    char buffer[1024];
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    if (n <= 0) break;
    seen.append(buffer, static_cast<std::size_t>(n));
    shown = updates(seen);
    if (!shown.empty() && first_after.count() == 0.0) first_after = Clock::now() - started;
  }
  const int status = stop_and_wait(child_);
  child_ = -1;
  ::close(master);
  ASSERT_EQ(shown.size(), 2u) << "what the terminal showed:\n" << seen;
  for (const Update& u : shown) {
    EXPECT_DOUBLE_EQ(u.duration, kDurationS);
    EXPECT_EQ(u.percent, static_cast<int>(std::lround(100.0 * u.t / kDurationS)));
  }
  EXPECT_GT(shown[0].t, 0.0);
  EXPECT_GT(shown[1].t, shown[0].t) << "the second update is later in the run";
  // Nothing before 3 s of wall time (measured here from before the start, so it is an upper
  // bound on the run's own clock).
  EXPECT_GE(first_after.count(), 3.0);
  EXPECT_EQ(status, 130);
  EXPECT_NE(test::read_text(dir_ / "out").find("INTERRUPTED"), std::string::npos);
}

TEST_F(RunProgress, OnAPipeALongRunSaysNothingUntilItEnds) {
  const int err = ::open((dir_ / "err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(err, 0);
  child_ = start_run(dir_ / "out", err);
  ::close(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(4500));
  const int status = stop_and_wait(child_);
  child_ = -1;
  EXPECT_EQ(status, 130);
  const std::string out = test::read_text(dir_ / "out");
  // The run itself lasted past the 3 s after which a terminal would have shown progress.
  EXPECT_GT(wall_seconds(out), 3.25) << out;
  const std::string said = test::read_text(dir_ / "err");
  EXPECT_EQ(said.find("run: t ="), std::string::npos) << said;
  EXPECT_EQ(said.find('\r'), std::string::npos) << said;
}

}  // namespace
}  // namespace fl
