// Reads the paper's Table I from its data file (assets/paper/table1.yaml).
#pragma once

#include <string>

#include "core/paper_table.hpp"

namespace fl {

// Throws InputError (located) for a malformed file.
PaperTable load_paper_table(const std::string& file);

// The data file's path under an asset folder.
std::string paper_table_path(const std::string& asset_dir);

}  // namespace fl
