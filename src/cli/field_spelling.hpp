// The command line's spelling of a request's fields (io/field_ref.hpp): "geometry" is
// "--geometry", "slow_motion" "--slow-motion", a value follows the flag ("--geometry pair"); the
// few fields whose flag is not their name are listed in field_spelling.cpp. Every text of the
// lab's the command prints goes through spelled().
#pragma once

#include <string>
#include <string_view>

#include "io/field_ref.hpp"

namespace fl::cli {

// "--geometry pair".
std::string flag_of(const FieldMention& field);

// The text with every field spelled as a flag.
std::string spelled(std::string_view text);

}  // namespace fl::cli
