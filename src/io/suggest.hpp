// "did you mean 'spacing'?": the closest known word to a misspelt one.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace fl {

// Edit distance (insertions, deletions, substitutions, adjacent swaps), case-insensitive.
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` if it is close enough to be a plausible typo, else "".
std::string closest_match(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace fl
