#include "hall_log/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

// Linux's termios2, for a baud rate that is not one of the Bnnn constants (it cannot be included
// with <termios.h>, whose struct termios it redefines).
#include <asm/termbits.h>

#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {

SerialPort::SerialPort(const std::string& path, int baud) : path_(path) {
  const SourceLocation at{path, 0, 0};
  if (baud <= 0)
    throw InputError(SourceLocation::of_field("follow.baud"),
                     "expected a positive baud rate, such as 250000");
  fd_ = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int error = errno;
    if (error == ENOENT) throw InputError(at, said("port-not-there"));
    if (error == EACCES) throw InputError(at, said("port-not-allowed"));
    if (error == EBUSY) throw InputError(at, said("port-busy"));
    throw InputError(at, "cannot open the serial port: " + std::string(std::strerror(error)));
  }
  struct termios2 t {};
  if (::ioctl(fd_, TCGETS2, &t) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw InputError(at,
                     "expected a serial port (a terminal device), found a file that is not "
                     "one: " +
                         std::string(std::strerror(error)));
  }
  // Raw: what cfmakeraw() does, with the speed given as a number.
  t.c_iflag &= ~static_cast<tcflag_t>(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL |
                                      IXON | IXOFF | IXANY);
  t.c_oflag &= ~static_cast<tcflag_t>(OPOST);
  t.c_lflag &= ~static_cast<tcflag_t>(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
  t.c_cflag &=
      ~static_cast<tcflag_t>(CSIZE | PARENB | CSTOPB | CRTSCTS | CBAUD | (CBAUD << IBSHIFT));
  t.c_cflag |= static_cast<tcflag_t>(CS8 | CREAD | CLOCAL | BOTHER | (BOTHER << IBSHIFT));
  t.c_ispeed = static_cast<speed_t>(baud);
  t.c_ospeed = static_cast<speed_t>(baud);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  if (::ioctl(fd_, TCSETS2, &t) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw InputError(at, "cannot set the serial port to " + std::to_string(baud) +
                             " baud, raw: " + std::strerror(error));
  }
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

bool SerialPort::read_some(std::string* out, int timeout_ms) {
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0) return errno == EINTR;
  if (ready == 0) return true;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      out->append(buffer, static_cast<std::size_t>(n));
      if (static_cast<std::size_t>(n) < sizeof buffer) return true;
      continue;
    }
    if (n == 0) return (p.revents & POLLHUP) == 0;
    if (errno == EAGAIN || errno == EINTR) return true;
    return false;  // EIO: the device went away
  }
}

}  // namespace fl
