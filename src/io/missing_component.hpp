// The error for a component this build of frictionlab was configured without: rendering, a GL
// back end, video, mesh import, the video module. One type for every layer (the render and
// assets layers name it too), so a caller catches one thing and the user reads one shape of
// message: "<what> needs <component>, which this build of frictionlab does not have (<how to
// get it>)". Header only: any layer includes it without linking another library. Tests skip
// on the layers' kHas... constants rather than on this error.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace fl {

class MissingComponent : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws MissingComponent with the message above.
[[noreturn]] inline void throw_missing(std::string_view what, std::string_view component,
                                       std::string_view how) {
  throw MissingComponent(std::string(what) + " needs " + std::string(component) +
                         ", which this build of frictionlab does not have (" + std::string(how) +
                         ")");
}

}  // namespace fl
