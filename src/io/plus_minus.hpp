// A measured value with its uncertainty, as every front end shows it ("0.2948 +- 0.0021"): the
// lab's one rule, which the page keeps too (web/src/format.ts), both held to the same cases
// (tests/data/plus_minus_cases.json). The uncertainty shows one significant digit, two where
// that digit is a 1 (0.0038, but 0.012), after rounding; the value the same decimals; never fewer
// than `min_decimals` (a table's column), never more than 15. An uncertainty of 0 or one that is
// not a number prints as it is.
#pragma once

#include <string>
#include <string_view>

namespace fl {

// `sign` between them: "+-" in text and files, "±" where the font has it (a video's frames).
std::string plus_minus(double value, double uncertainty, int min_decimals,
                       std::string_view sign = "+-");

}  // namespace fl
