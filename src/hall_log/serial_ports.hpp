// The serial ports a rig's Arduino may be on: the names udev gives USB serial devices, which say
// which board it is (/dev/serial/by-id/...), then the devices themselves (/dev/ttyACM*, an Uno's;
// /dev/ttyUSB*, a clone's USB-serial chip), each list sorted. What the browser's live rig offers.
#pragma once

#include <string>
#include <vector>

namespace fl {

// `dev`: the device folder (/dev; another for a test).
std::vector<std::string> list_serial_ports(const std::string& dev = "/dev");

}  // namespace fl
