// Command-line values with units: "--spacing 89mm". Errors name the option.
#pragma once

#include <string>

#include "core/units.hpp"

namespace fl::cli {

// Parses an option's text; throws InputError "error: --spacing: expected a length ..." .
double option_quantity(const std::string& text, Dimension dimension, const std::string& option);

}  // namespace fl::cli
