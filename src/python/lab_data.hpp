// Where the module finds the lab's data (the paper's Table I, the LEGO part index): the `assets`
// argument, else $FRICTIONLAB_ASSETS, else the build's assets/ folder, as the frictionlab command
// finds them. Each file is read once per process and folder, the first time something needs it,
// and is then shared by every scene, run and sweep (safe from several threads).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/paper_table.hpp"
#include "lab/sweep_spec.hpp"

namespace fl::python {

std::string asset_dir(const std::optional<std::filesystem::path>& given);

// The paper's table and the part index under `asset_dir`, each read when first called.
SceneInputs scene_inputs(const std::string& asset_dir);

// The paper's table under `asset_dir` (read now if it has not been).
const PaperTable& paper_table_in(const std::string& asset_dir);

}  // namespace fl::python
