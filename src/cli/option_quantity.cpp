#include "cli/option_quantity.hpp"

#include <cstdlib>

#include "io/input_error.hpp"

namespace fl::cli {

double option_quantity(const std::string& text, Dimension dimension, const std::string& option) {
  try {
    return parse_quantity(text, dimension, option);
  } catch (const UnitError& e) {
    throw InputError(SourceLocation{}, e.what());
  }
}

std::string resolve_asset_dir(const std::string& option_value) {
  if (!option_value.empty()) return option_value;
  if (const char* env = std::getenv("FRICTIONLAB_ASSETS"); env != nullptr && *env != '\0')
    return env;
  return FRICTIONLAB_DEFAULT_ASSET_DIR;
}

}  // namespace fl::cli
