// A live session's request (the browser's page): a scene chosen by name from a scenes folder and
// the overrides after it, exactly as `frictionlab run SCENE --set ...` takes them. It is a run's
// request (run_request.hpp) with nothing written and no frames: the same checks, defaults and
// compiled rig, so a session's run is the run `run` makes for the same set-up.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/accepted_ranges.hpp"
#include "scene/compiled_rig.hpp"
#include "scene/scene.hpp"

namespace fl {

// A scene a folder offers: its name (the file's stem) and what its first comment line says.
struct SceneEntry {
  std::string name;
  std::string title;
};

// The `*.yaml` files directly in `folder` whose path, links followed, stays inside it, by name;
// none when it is not a folder. A file or link leading outside is neither listed nor read: asked
// for, it is refused as a name not there.
std::vector<SceneEntry> list_scenes(const std::string& folder);

struct SessionRequest {
  std::string scene;             // field "scene": a name list_scenes gives (never a path)
  std::vector<std::string> set;  // field "set": "key.path=value", as run's
};

struct PreparedSession {
  std::shared_ptr<const CompiledRig> rig;
  OutputDesc output;                   // the scene's output part: the files the run keeps
  std::vector<std::string> warnings;   // field_ref mentions, for the front end to spell
  std::vector<AcceptedRange> accepts;  // what the set-up's controls may offer (accepted_ranges)
};

// Reads and checks the request against the scenes `folder` (and the data in `asset_dir`,
// lab/request/lab_data.hpp); throws RequestError (every problem by field) or InputError located
// at a `set` entry or in the scene's file.
PreparedSession prepare_session(const SessionRequest& request, const std::string& folder,
                                const std::string& asset_dir);

}  // namespace fl
