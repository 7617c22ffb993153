// import frictionlab: the lab from Python, over the same libraries the frictionlab command uses.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <pybind11/pybind11.h>

#include "python/bindings.hpp"
#include "tracking/video_decoder_module.hpp"

namespace {

// The decoder module beside this Python module (an installed copy), else the build's: where the
// tracker looks when $FRICTIONLAB_DECODER_MODULE does not say (it would look beside the running
// executable, which is python3).
void find_decoder_module() {
  const char* env = std::getenv(fl::kVideoDecoderVariable);
  if (env != nullptr && *env != '\0') return;
  std::string path = FRICTIONLAB_PYTHON_DECODER_MODULE;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&find_decoder_module), &info) != 0 &&
      info.dli_fname != nullptr) {
    const std::filesystem::path beside =
        std::filesystem::path(info.dli_fname).parent_path() / fl::kVideoDecoderFile;
    std::error_code ec;
    if (std::filesystem::is_regular_file(beside, ec)) path = beside.string();
  }
  if (!path.empty()) setenv(fl::kVideoDecoderVariable, path.c_str(), 0);
}

}  // namespace

PYBIND11_MODULE(frictionlab, m) {
  m.doc() =
      "frictionlab: a virtual lab of the friction (Timoshenko) oscillator.\n\n"
      "A plate on two rollers spinning in opposite senses oscillates with period\n"
      "T = pi sqrt(2 l / (mu_k g)). The functions here are the frictionlab command's:\n"
      "load_scene and run (a simulation and its typed summary, the trajectory and the Hall\n"
      "samples as NumPy arrays), estimate and estimate_file (the rig's period estimator on a\n"
      "Hall signal), analytic, paper_table, sweep, fit (mu_k and h_c from a spacing\n"
      "series), compare, accuracy and stability, track (a phone's video of the rig). Quantities "
      "are SI; arguments that are\n"
      "quantities also take text with units, the way the paper writes them (\"89mm\", "
      "\"1600rpm\").\n"
      "Bad input raises InputError with the message the command prints (file:line:column).";
  m.attr("__version__") = FRICTIONLAB_VERSION;
  find_decoder_module();
  fl::python::bind_input_error(m);
  fl::python::bind_common_types(m);
  fl::python::bind_scene(m);
  fl::python::bind_run(m);
  fl::python::bind_estimate(m);
  fl::python::bind_analytic(m);
  fl::python::bind_paper_table(m);
  fl::python::bind_sweep(m);
  fl::python::bind_fit(m);
  fl::python::bind_studies(m);
  fl::python::bind_track(m);
  fl::python::bind_report(m);
}
