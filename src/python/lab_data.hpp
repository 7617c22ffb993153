// Where the module finds the lab's data: the `assets` argument, else what every front end reads
// (lab/request/lab_data.hpp: $FRICTIONLAB_ASSETS, else the build's assets/ folder).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "lab/request/lab_data.hpp"

namespace fl::python {

std::string asset_dir(const std::optional<std::filesystem::path>& given);

}  // namespace fl::python
