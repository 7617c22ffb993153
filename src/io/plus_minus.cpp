#include "io/plus_minus.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace fl {

std::string plus_minus(double value, double uncertainty, int min_decimals, std::string_view sign) {
  int decimals = min_decimals;
  if (uncertainty > 0.0 && std::isfinite(uncertainty)) {
    // The uncertainty rounded to two significant digits decides (0.0999 is 0.10): a leading 1
    // keeps both digits.
    double exponent = std::floor(std::log10(uncertainty));
    if (std::round(uncertainty / std::pow(10.0, exponent - 1.0)) >= 100.0) exponent += 1.0;
    const bool leading_one = std::round(uncertainty / std::pow(10.0, exponent - 1.0)) < 20.0;
    int shown = -static_cast<int>(exponent) + (leading_one ? 1 : 0);
    decimals = std::clamp(std::max(min_decimals, shown), 0, 15);
  }
  return fmt::format("{:.{}f} {} {:.{}f}", value, decimals, sign, uncertainty, decimals);
}

}  // namespace fl
