// The options every command that reads a scene shares: the file, --set overrides, --duration.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "lab/request/scene_source.hpp"
#include "scene/scene.hpp"
#include "scene/scene_yaml.hpp"

namespace fl::cli {

struct SceneOptions {
  std::string file;
  std::vector<std::string> overrides;  // --set key.path=value
  std::string duration;                // --duration, overrides world.duration
};

void add_scene_options(CLI::App& command, SceneOptions& options);

// The scene file and the asset folder as a request's scene (lab/request/scene_source.hpp); the
// overrides and the duration are the request's own fields.
SceneSource scene_source_of(const SceneOptions& options, const GlobalOptions& global);

}  // namespace fl::cli
