#include "cli/option_quantity.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace fl::cli {

double option_quantity(const std::string& text, Dimension dimension, const std::string& option) {
  double value = 0.0;
  try {
    value = parse_quantity(text, dimension, option);
  } catch (const UnitError& e) {
    throw InputError(SourceLocation{}, e.what());
  }
  // A plain number is SI: a length of metres where the rig measures millimetres is said aloud.
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const bool plain = end != nullptr && end != text.c_str() && *end == '\0';
  if (plain && dimension == Dimension::kLength && std::fabs(value) >= 2.0)
    fmt::print(stderr,
               "warning: {} {} read as {} m (a plain number is SI); write {}mm for millimetres\n",
               option, text, text, text);
  return value;
}

}  // namespace fl::cli
