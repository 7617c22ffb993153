#include <cmath>

#include "hall_log/serial_port.hpp"

namespace fl {

std::optional<std::string> baud_problem(double baud) {
  if (baud >= 1.0 && baud <= 4e6 && baud == std::floor(baud)) return std::nullopt;
  return "expected a whole baud rate from 1 to 4000000, such as " + std::to_string(kFirmwareBaud) +
         " (the firmware's)";
}

}  // namespace fl
