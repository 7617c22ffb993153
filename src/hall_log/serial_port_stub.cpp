// The browser's build (Emscripten) has no serial device files: a port named is refused, saying
// what the page offers instead (its own Connect button, through the browser's Web Serial).
#include "hall_log/serial_port.hpp"
#include "io/input_error.hpp"

namespace fl {

SerialPort::SerialPort(const std::string& path, int) : path_(path) {
  throw InputError(SourceLocation{path, 0, 0},
                   "this build of the lab runs in a browser, which opens no serial device "
                   "file: connect the rig with the page's own button (Web Serial), or save its "
                   "log and choose the file");
}

SerialPort::~SerialPort() = default;

bool SerialPort::read_some(std::string*, int) {
  return false;
}

}  // namespace fl
