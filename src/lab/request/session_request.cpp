#include "lab/request/session_request.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/field_ref.hpp"
#include "io/suggest.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/run_request.hpp"

namespace fl {
namespace {

// The first comment line's text ("# The paper's rig: ..." gives "The paper's rig: ...").
std::string first_comment(const std::filesystem::path& file) {
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

// Whether `path`, every link followed, is a regular file inside `root` (itself resolved): a
// scene that is a link leading outside the folder is neither listed nor read.
bool is_file_inside(const std::filesystem::path& path, const std::filesystem::path& root) {
  std::error_code error;
  const std::filesystem::path resolved = std::filesystem::canonical(path, error);
  if (error || !std::filesystem::is_regular_file(resolved, error)) return false;
  const auto [in_root, in_resolved] =
      std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  return in_root == root.end() && in_resolved != resolved.end();
}

// Whether the folder offers the scene `name`: a file's stem directly in it (no separator, no
// leading dot) whose file, links followed, lies inside it.
bool offers(const std::string& folder, const std::string& name) {
  if (name.empty() || name.front() == '.' || name.find_first_of("/\\") != std::string::npos)
    return false;
  std::error_code error;
  const std::filesystem::path root = std::filesystem::canonical(folder, error);
  return !error && is_file_inside(std::filesystem::path(folder) / (name + ".yaml"), root);
}

}  // namespace

std::vector<SceneEntry> list_scenes(const std::string& folder) {
  std::vector<SceneEntry> out;
  std::error_code error;
  const std::filesystem::path root = std::filesystem::canonical(folder, error);
  if (error || !std::filesystem::is_directory(root, error)) return out;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.path().extension() != ".yaml" || !is_file_inside(entry.path(), root)) continue;
    out.push_back({entry.path().stem().string(), first_comment(entry.path())});
  }
  std::sort(out.begin(), out.end(),
            [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
  return out;
}

PreparedSession prepare_session(const SessionRequest& request, const std::string& folder,
                                const std::string& asset_dir) {
  // The scene by name only: nothing a client sends names a path on the server. A name is a
  // file's stem in the folder itself (no separator, no leading dot) that, links followed, lies
  // inside it; the folder is listed only to say which names there are.
  if (!offers(folder, request.scene)) {
    std::vector<std::string> names;
    for (const SceneEntry& s : list_scenes(folder)) names.push_back(s.name);
    FieldChecks checks;
    const std::vector<std::string_view> views(names.begin(), names.end());
    const std::string near = closest_match(request.scene, views);
    checks.problem(
        "scene", request.scene,
        names.empty() ? std::string("expected a scene's name, found none offered: the scenes "
                                    "folder holds no .yaml file")
                      : fmt::format("expected one of the scenes offered ({}), found \"{}\"{}",
                                    fmt::join(names, ", "), request.scene,
                                    near.empty() ? "" : fmt::format("; did you mean '{}'?", near)));
    checks.throw_if_any();
  }
  RunRequest run;
  run.scene.file = (std::filesystem::path(folder) / (request.scene + ".yaml")).string();
  run.scene.asset_dir = asset_dir;
  run.set = request.set;
  PreparedRun prepared = prepare_run(run);
  return {std::move(prepared.rig), prepared.output, std::move(prepared.warnings),
          accepted_ranges(*prepared.scene)};
}

}  // namespace fl
