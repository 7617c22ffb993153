// A decimal number read from text the way std::from_chars reads a double (general format, no
// leading blank or '+', no hexadecimal; "inf" and "nan" as words), on every standard library:
// Emscripten's libc++ 13, which builds the lab for the browser, has no std::from_chars for
// double.
#pragma once

#include <charconv>

namespace fl {

// Reads the longest decimal number at the start of [first, last) into `value`, correctly
// rounded. Returns where the number ends and std::errc{}; or `first` and invalid_argument when
// the text starts with no number (value unchanged); or the end and result_out_of_range when its
// magnitude is beyond a double's range (value unchanged).
std::from_chars_result read_decimal(const char* first, const char* last, double& value);

// The same, by the C library's strtod on the number's text alone: what read_decimal is where
// std::from_chars for double is missing (tests/text/decimal_test.cpp holds it to std::from_chars
// where that is present).
std::from_chars_result read_decimal_by_strtod(const char* first, const char* last, double& value);

}  // namespace fl
