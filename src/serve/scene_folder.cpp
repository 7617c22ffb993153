#include "serve/scene_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/suggest.hpp"
#include "lab/request/field_checks.hpp"

namespace fl::serve {
namespace {

namespace fs = std::filesystem;

// The first comment line's text ("# The paper's rig: ..." gives "The paper's rig: ...").
std::string first_comment(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos) continue;
    if (line[start] != '#') return "";
    const auto text = line.find_first_not_of("# \t", start);
    return text == std::string::npos ? "" : line.substr(text);
  }
  return "";
}

// Whether `path`, every link followed, is a regular file inside `root` (itself resolved).
bool is_file_inside(const fs::path& path, const fs::path& root) {
  std::error_code error;
  const fs::path resolved = fs::canonical(path, error);
  if (error || !fs::is_regular_file(resolved, error)) return false;
  const auto [in_root, in_resolved] =
      std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  return in_root == root.end() && in_resolved != resolved.end();
}

// A name that can only be a file's stem directly in the folder: no separator, no leading dot.
bool is_plain_name(const std::string& name) {
  return !name.empty() && name.front() != '.' && name.find_first_of("/\\") == std::string::npos;
}

}  // namespace

std::vector<SceneEntry> SceneFolder::list() const {
  std::vector<SceneEntry> out;
  std::error_code error;
  const fs::path root = fs::canonical(folder_, error);
  if (error || !fs::is_directory(root, error)) return out;
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    if (entry.path().extension() != ".yaml" || !is_file_inside(entry.path(), root)) continue;
    out.push_back({entry.path().stem().string(), first_comment(entry.path())});
  }
  std::sort(out.begin(), out.end(),
            [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
  return out;
}

bool SceneFolder::offers(const std::string& name) const {
  if (!is_plain_name(name)) return false;
  std::error_code error;
  const fs::path root = fs::canonical(folder_, error);
  return !error && is_file_inside(fs::path(folder_) / (name + ".yaml"), root);
}

void SceneFolder::check(const std::string& name) const {
  if (offers(name)) return;
  std::vector<std::string> names;
  for (const SceneEntry& s : list()) names.push_back(s.name);
  const std::vector<std::string_view> views(names.begin(), names.end());
  const std::string near = closest_match(name, views);
  FieldChecks checks;
  checks.problem(
      "scene", name,
      names.empty()
          ? std::string("expected a scene's name, found none offered: the scenes folder holds no "
                        ".yaml file")
          : fmt::format("expected one of the scenes offered ({}), found \"{}\"{}",
                        fmt::join(names, ", "), name,
                        near.empty() ? "" : fmt::format("; did you mean '{}'?", near)));
  checks.throw_if_any();
}

}  // namespace fl::serve
