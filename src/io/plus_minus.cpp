#include "io/plus_minus.hpp"

#include <cmath>

#include <fmt/format.h>

namespace fl {

std::string plus_minus(double value, double uncertainty, int decimals) {
  int shown = decimals;
  // The decimals that give a positive uncertainty two significant digits, past those asked for.
  if (uncertainty > 0.0 && std::isfinite(uncertainty)) {
    const int first = -static_cast<int>(std::floor(std::log10(uncertainty)));  // its first digit
    shown = std::max(decimals, std::min(first + 1, 15));
  }
  return fmt::format("{:.{}f} +- {:.{}f}", value, shown, uncertainty, shown);
}

}  // namespace fl
