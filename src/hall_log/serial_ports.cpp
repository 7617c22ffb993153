#include "hall_log/serial_ports.hpp"

#include <algorithm>
#include <filesystem>

namespace fl {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& folder, bool (*wanted)(const std::string&)) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (wanted(name)) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool any_name(const std::string&) {
  return true;
}
bool tty_serial(const std::string& name) {
  return name.starts_with("ttyACM") || name.starts_with("ttyUSB");
}

}  // namespace

std::vector<std::string> list_serial_ports(const std::string& dev) {
  std::vector<std::string> out = entries(fs::path(dev) / "serial" / "by-id", any_name);
  for (std::string& port : entries(dev, tty_serial)) out.push_back(std::move(port));
  return out;
}

}  // namespace fl
