// frictionlab serve's refusals before it serves: each says what is wrong and exits 2.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>

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

}  // namespace
}  // namespace fl
