// Command-line values with units: "--spacing 89mm". Errors name the option.
#pragma once

#include <string>

#include "core/units.hpp"

namespace fl::cli {

// Parses an option's text; throws InputError "error: --spacing: expected a length ..." .
double option_quantity(const std::string& text, Dimension dimension, const std::string& option);

// Resolves the asset folder: the option if given, else $FRICTIONLAB_ASSETS, else the build's.
std::string resolve_asset_dir(const std::string& option_value);

}  // namespace fl::cli
