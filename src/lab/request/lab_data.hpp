// Where every front end finds the lab's data (the paper's Table I, the LEGO part index) and its
// tools (the plotting scripts): the request's `assets` field, else $FRICTIONLAB_ASSETS, else the
// build's assets/ folder. Each file is read once per process and folder, the first time
// something needs it, and then shared by every scene, run and sweep (safe from several threads).
#pragma once

#include <string>

#include "core/paper_table.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

// The asset folder: `given` if not empty, else $FRICTIONLAB_ASSETS, else the build's.
std::string asset_dir(const std::string& given);

// The paper's table and the part index under `asset_dir`, each read when first called.
SceneInputs scene_inputs(const std::string& asset_dir);

// The paper's table under `asset_dir` (read now if it has not been).
const PaperTable& paper_table_in(const std::string& asset_dir);

}  // namespace fl
