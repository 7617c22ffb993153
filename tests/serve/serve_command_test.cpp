// frictionlab serve's refusals before it serves (each says what is wrong and exits 2: a port in
// use, by another program or another serve), and its end at SIGTERM: exit 0, the rig's log
// written whole.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;

class ServeCommandTest : public test::TempFolderTest {
 protected:
  ServeCommandTest() : TempFolderTest("serve-command") {}
};

TEST_F(ServeCommandTest, APortInUseIsBadInputSayingWhatToDo) {
  // Hold a port, then ask the server for it.
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(fd, 1), 0);
  socklen_t length = sizeof address;
  ASSERT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const int port = ntohs(address.sin_port);
  write("web/index.html", "<!doctype html>");
  const auto r = test::run_command(kExe + " serve --port " + std::to_string(port) + " --web " +
                                   (dir_ / "web").string());
  ::close(fd);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--port " + std::to_string(port)), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 for any free one"), std::string::npos) << r.err;
}

TEST_F(ServeCommandTest, ASecondServeOnAPortInUseExitsWithStatus2SayingSo) {
  // A first serve, on a port the system chose; its address says which.
  write("web/index.html", "<!doctype html>");
  const std::string web = (dir_ / "web").string();
  const std::string out = (dir_ / "first").string();
  const pid_t first = ::fork();
  ASSERT_GE(first, 0);
  if (first == 0) {
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execl(kExe.c_str(), kExe.c_str(), "serve", "--port", "0", "--web", web.c_str(), nullptr);
    ::_exit(127);
  }
  const std::string said = "the lab at http://127.0.0.1:";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (test::read_text(out).find(said) == std::string::npos &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::string first_said = test::read_text(out);
  const auto at = first_said.find(said);
  ASSERT_NE(at, std::string::npos) << first_said;
  const std::string port = std::to_string(std::stoi(first_said.substr(at + said.size())));

  // The second is told the port is in use and what to do, and leaves the first alone.
  const auto second = test::run_command(kExe + " serve --port " + port + " --web " + web);
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find("port " + port + " on 127.0.0.1 is in use"), std::string::npos)
      << second.err;
  EXPECT_NE(second.err.find("--port 0 for any free one"), std::string::npos) << second.err;
  EXPECT_EQ(second.out.find("the lab at"), std::string::npos) << second.out;
  int status = 0;
  EXPECT_EQ(::waitpid(first, &status, WNOHANG), 0) << "the first serve ended";
  ASSERT_EQ(::kill(first, SIGTERM), 0);
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << test::read_text(out);
}

TEST_F(ServeCommandTest, AMissingPageOrScenesFolderIsBadInput) {
  const auto no_page =
      test::run_command(kExe + " serve --port 0 --web " + (dir_ / "none").string());
  EXPECT_EQ(no_page.status, 2) << no_page.err;
  EXPECT_NE(no_page.err.find("index.html"), std::string::npos) << no_page.err;
  write("web/index.html", "<!doctype html>");
  const auto no_scenes =
      test::run_command(kExe + " serve --port 0 --web " + (dir_ / "web").string() + " --scenes " +
                        (dir_ / "none").string());
  EXPECT_EQ(no_scenes.status, 2) << no_scenes.err;
  EXPECT_NE(no_scenes.err.find("--scenes DIR"), std::string::npos) << no_scenes.err;
}

TEST_F(ServeCommandTest, ABadRecordFolderOrBaudIsBadInput) {
  write("web/index.html", "<!doctype html>");
  const std::string web = " --port 0 --web " + (dir_ / "web").string();
  const std::string file = write("a-file", "");
  const auto record = test::run_command(kExe + " serve" + web + " --record " + file + "/rec");
  EXPECT_EQ(record.status, 2) << record.err;
  EXPECT_NE(record.err.find("give another --record"), std::string::npos) << record.err;
  const auto baud = test::run_command(kExe + " serve" + web + " --baud 9600.5");
  EXPECT_EQ(baud.status, 2) << baud.err;
  EXPECT_NE(baud.err.find("whole baud rate"), std::string::npos) << baud.err;
}

TEST_F(ServeCommandTest, SigtermEndsItWithTheRigsLogWritten) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(::grantpt(master), 0);
  ASSERT_EQ(::unlockpt(master), 0);
  const std::string port = ::ptsname(master);
  write("web/index.html", "<!doctype html>");
  const std::string out = (dir_ / "out").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    std::vector<std::string> args = {kExe,       "serve",
                                     "--port",   "0",
                                     "--web",    (dir_ / "web").string(),
                                     "--serial", port,
                                     "--record", (dir_ / "rec").string()};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(kExe.c_str(), argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (test::read_text(out).find("the live rig from") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::string sent = "t_us,adc\r\n";
  for (int i = 0; i < 200; ++i) sent += std::to_string(1000 * i) + ",512\r\n";
  ASSERT_EQ(::write(master, sent.data(), sent.size()), static_cast<ssize_t>(sent.size()));
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ASSERT_EQ(::kill(child, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ::close(master);
  const std::string said = test::read_text(out);
  ASSERT_TRUE(WIFEXITED(status)) << said;
  EXPECT_EQ(WEXITSTATUS(status), 0) << said;
  const auto at = said.find("the rig's log: ");
  ASSERT_NE(at, std::string::npos) << said;
  const std::string log = said.substr(at + 15, said.find('\n', at) - at - 15);
  EXPECT_EQ(std::filesystem::path(log).parent_path(), dir_ / "rec");
  EXPECT_EQ(test::read_text(log), sent);
}

}  // namespace
}  // namespace fl
