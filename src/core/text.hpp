// Small text helpers shared by the readers of quantities, logs and sweep files.
#pragma once

#include <string_view>

namespace fl {

// Spaces, tabs and line ends: what trim() strips unless told otherwise.
inline constexpr std::string_view kWhitespace = " \t\r\n";

// `s` without leading and trailing characters from `strip`.
std::string_view trim(std::string_view s, std::string_view strip = kWhitespace);

}  // namespace fl
