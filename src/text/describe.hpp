// Builds a message from pieces, numbers written with enough digits to be exact enough to read
// back (the core uses the standard library only, no formatting library).
#pragma once

#include <sstream>
#include <string>

namespace fl {

template <typename... Parts>
std::string describe(const Parts&... parts) {
  std::ostringstream out;
  out.precision(6);
  (out << ... << parts);
  return out.str();
}

}  // namespace fl
