// Runs one of the plotting scripts in tools/ (python3 + matplotlib) to draw a PNG.
#pragma once

#include <string>
#include <vector>

namespace fl::cli {

// Folder of the plotting scripts: $FRICTIONLAB_TOOLS, else the source tree's tools/.
std::string tools_dir();

// Runs `python3 tools/<script> args...` (no shell). Throws std::runtime_error naming the script
// and its exit status if it fails.
void run_plot_script(const std::string& script, const std::vector<std::string>& args);

}  // namespace fl::cli
