// Messages as a browser sees them: the server's folders named by what they are, never by their
// place on the laptop. A scene's error located at "/home/teacher/lab/scenes/x.yaml:3:5" reaches
// the page as "x.yaml:3:5"; a data file's as "assets/...".
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace fl::serve {

class PathScrubber {
 public:
  // `folder` (as given, absolute, and with its links resolved) reads as `name` from now on, a
  // path in it as `prefix` and the rest ("" : the rest alone). The longest folder that matches
  // is replaced.
  void add(const std::string& folder, const std::string& prefix, const std::string& name);
  std::string scrubbed(std::string_view message) const;
  // An error's body (api_json.hpp): its "error", and each problem's "message" and "value".
  nlohmann::json scrubbed_body(nlohmann::json body) const;

 private:
  struct Replacement {
    std::string path;
    std::string by;
    bool whole;  // a folder itself: matched only where a name cannot go on
  };
  std::vector<Replacement> replacements_;  // longest path first
};

}  // namespace fl::serve
