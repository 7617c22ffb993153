// Runs one of the plotting scripts in tools/ (python3 + matplotlib) to draw a PNG: every front end
// draws its plots through it (a plot that fails leaves the results, and the job is incomplete).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fl {

// Folder of the plotting scripts: $FRICTIONLAB_TOOLS, else the source tree's tools/.
std::string tools_dir();

// Runs `python3 tools/<script> args...` (no shell). Throws std::runtime_error naming the script
// and its exit status if it fails.
void run_plot_script(const std::string& script, const std::vector<std::string>& args);

// Writes `data` to a temporary JSON file, runs `python3 tools/<script> that.json png`, and
// removes the file whatever happens. Throws std::runtime_error as run_plot_script does.
void run_plot_script_on(const std::string& script, const nlohmann::json& data,
                        const std::string& png);

}  // namespace fl
