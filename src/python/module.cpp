// import frictionlab: the lab from Python, over the same libraries the frictionlab command uses.
#include <pybind11/pybind11.h>

#include "python/bindings.hpp"

PYBIND11_MODULE(frictionlab, m) {
  m.doc() =
      "frictionlab: a virtual lab of the friction (Timoshenko) oscillator.\n\n"
      "A plate on two rollers spinning in opposite senses oscillates with period\n"
      "T = pi sqrt(2 l / (mu_k g)). The functions here are the frictionlab command's:\n"
      "load_scene and run (a simulation and its typed summary, the trajectory and the Hall\n"
      "samples as NumPy arrays), estimate and estimate_file (the rig's period estimator on a\n"
      "Hall signal), analytic, paper_table, sweep, fit (mu_k and h_c from a spacing\n"
      "series), compare, accuracy and stability. Quantities are SI; arguments that are\n"
      "quantities also take text with units, the way the paper writes them (\"89mm\", "
      "\"1600rpm\").\n"
      "Bad input raises InputError with the message the command prints (file:line:column).";
  m.attr("__version__") = FRICTIONLAB_VERSION;
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
}
