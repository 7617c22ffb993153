// frictionlab-api-recording SPEC OUT --root DIR --assets DIR: records what the lab's server answers
// for the set-ups SPEC lists (serve/api_recording.hpp) into OUT, for the page's mock server
// (web/tests/mock_server.mjs). SPEC (web/tests/mock_recording.json): {"scenes": [scene files
// relative to --root], "duration": "8s" (for set-ups naming none), "setups": [{"scene", "set"}],
// "board": {"scene", "set"}}.
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "serve/api_recording.hpp"

namespace {

fl::SessionRequest session_request(const nlohmann::json& j) {
  return {j.at("scene").get<std::string>(), j.value("set", std::vector<std::string>{})};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  std::string root = ".";
  std::string assets;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--root" || arg == "--assets") && i + 1 < argc)
      (arg == "--root" ? root : assets) = argv[++i];
    else
      files.push_back(arg);
  }
  if (files.size() != 2 || assets.empty()) {
    std::fprintf(stderr,
                 "usage: frictionlab-api-recording SPEC OUT --root REPOSITORY --assets DIR\n");
    return 2;
  }
  try {
    std::ifstream in(files[0]);
    if (!in) throw std::runtime_error(files[0] + ": cannot read it");
    const nlohmann::json spec = nlohmann::json::parse(in);
    fl::serve::ApiRecordingRequest request;
    for (const auto& scene : spec.at("scenes"))
      request.scene_files.push_back(root + "/" + scene.get<std::string>());
    request.asset_dir = assets;
    request.version = "frictionlab (recorded for the page's mock server)";
    request.duration_entry = "world.duration=" + spec.at("duration").get<std::string>();
    for (const auto& setup : spec.at("setups")) request.setups.push_back(session_request(setup));
    request.board = session_request(spec.at("board"));
    fl::write_file_atomic(files[1], fl::serve::record_api(request).dump() + "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frictionlab-api-recording: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
