// The browser's build (Emscripten) starts no program: the plots that python3 and matplotlib draw
// are refused, saying so (the page draws its own plots; `frictionlab` on a computer draws these).
#include <stdexcept>

#include "lab/request/plot_script.hpp"

namespace fl {

std::string tools_dir() {
  return "";
}

void run_plot_script(const std::string& script, const std::vector<std::string>&) {
  throw std::runtime_error(
      "this build of the lab runs in a browser, which runs no python3: the "
      "plot of tools/" +
      script + " is drawn by frictionlab on a computer");
}

void run_plot_script_on(const std::string& script, const nlohmann::json&, const std::string&) {
  run_plot_script(script, {});
}

}  // namespace fl
