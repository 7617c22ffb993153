// The rig's serial port (the Uno's USB serial device, /dev/ttyACM0, or any terminal device, a
// pseudo-terminal included): opened raw, as the firmware's bytes must arrive (no echo, no line
// editing, no translation of '\r' or '\n', no flow control), 8 data bits, no parity, one stop
// bit, at any baud rate (the firmware's 250000 is not one of the POSIX speeds: it is set through
// Linux's termios2 and BOTHER). Opening the port resets an Uno (DTR), so its output starts with
// the firmware's header.
#pragma once

#include <optional>
#include <string>

namespace fl {

// The firmware's baud rate (tools/arduino): what a port is opened at when nothing else is said.
inline constexpr int kFirmwareBaud = 250000;

// Why `baud` is no rate a port can be opened at (a whole number from 1 to 4 000 000), or nothing.
std::optional<std::string> baud_problem(double baud);

class SerialPort {
 public:
  // Throws InputError located at `path` when it cannot be opened or set up, saying why.
  SerialPort(const std::string& path, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Waits up to `timeout_ms` for bytes and appends what came to `out`. Returns false when the
  // port is gone (the board unplugged, the other end of a pseudo-terminal closed); a signal only
  // cuts the wait short.
  bool read_some(std::string* out, int timeout_ms);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  [[maybe_unused]] int fd_ = -1;  // (unused by the browser's build, which opens no port)
};

}  // namespace fl
