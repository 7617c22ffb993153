#include "serve/path_scrubber.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fl::serve {

namespace {

// Whether a path's name may go on with `c` ("scenes" in "scenes-old").
bool continues_name(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '-' || c == '_';
}

}  // namespace

void PathScrubber::add(const std::string& folder, const std::string& prefix,
                       const std::string& name) {
  if (folder.empty()) return;
  namespace fs = std::filesystem;
  std::error_code error;
  std::vector<std::string> spellings{folder, fs::absolute(folder, error).string()};
  if (const fs::path resolved = fs::weakly_canonical(folder, error); !error)
    spellings.push_back(resolved.string());
  for (std::string spelling : spellings) {
    while (spelling.size() > 1 && spelling.ends_with('/')) spelling.pop_back();
    // The root, and a relative folder's bare name, would match in any text.
    if (spelling.size() <= 1 || !spelling.starts_with('/')) continue;
    replacements_.push_back({spelling + "/", prefix, false});
    replacements_.push_back({spelling, name, true});
  }
  std::stable_sort(
      replacements_.begin(), replacements_.end(),
      [](const Replacement& a, const Replacement& b) { return a.path.size() > b.path.size(); });
}

std::string PathScrubber::scrubbed(std::string_view message) const {
  std::string out;
  for (std::size_t at = 0; at < message.size();) {
    const std::string_view rest = message.substr(at);
    const auto match =
        std::find_if(replacements_.begin(), replacements_.end(), [&](const Replacement& r) {
          return rest.starts_with(r.path) &&
                 !(r.whole && rest.size() > r.path.size() && continues_name(rest[r.path.size()]));
        });
    if (match == replacements_.end()) {
      out += message[at++];
    } else {
      out += match->by;
      at += match->path.size();
    }
  }
  return out;
}

nlohmann::json PathScrubber::scrubbed_body(nlohmann::json body) const {
  const auto scrub = [this](nlohmann::json& value) {
    if (value.is_string()) value = scrubbed(std::string_view(value.get_ref<const std::string&>()));
  };
  if (!body.is_object()) return body;
  if (const auto error = body.find("error"); error != body.end()) scrub(*error);
  if (const auto problems = body.find("problems"); problems != body.end() && problems->is_array())
    for (nlohmann::json& problem : *problems) {
      if (!problem.is_object()) continue;
      for (const char* key : {"message", "value"})
        if (const auto it = problem.find(key); it != problem.end()) scrub(*it);
    }
  return body;
}

}  // namespace fl::serve
