#include "lab/request/plot_script.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

extern char** environ;

namespace fl {

std::string tools_dir() {
  if (const char* env = std::getenv("FRICTIONLAB_TOOLS"); env != nullptr && *env != '\0')
    return env;
  return FRICTIONLAB_DEFAULT_TOOLS_DIR;
}

namespace {

// Debian's python3, where python3-matplotlib installs, before any other on the PATH (a pyenv
// python there has no matplotlib); $FRICTIONLAB_PYTHON overrides both.
std::string python() {
  if (const char* env = std::getenv("FRICTIONLAB_PYTHON"); env != nullptr && *env != '\0')
    return env;
  if (access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

}  // namespace

void run_plot_script(const std::string& script, const std::vector<std::string>& args) {
  std::vector<std::string> argv_storage{python(), tools_dir() + "/" + script};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv_storage[0].c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot start python3 to run tools/" + script +
                             " (install python3 and python3-matplotlib: tools/install-deps)");
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the plotting script tools/" + script + " failed (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
}

void run_plot_script_on(const std::string& script, const nlohmann::json& data,
                        const std::string& png) {
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::filesystem::path json_path =
      std::filesystem::temp_directory_path() /
      ("frictionlab-plot-" + std::to_string(getpid()) + "-" + std::to_string(stamp) + ".json");
  struct Remove {
    std::filesystem::path path;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } remove_json{json_path};
  {
    std::ofstream f(json_path);
    f << data.dump();
    if (!f) throw std::runtime_error("cannot write " + json_path.string());
  }
  run_plot_script(script, {json_path.string(), png});
}

}  // namespace fl
