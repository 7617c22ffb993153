// frictionlab.fit: mu_k and h_c from periods measured at several roller spacings, as `frictionlab
// fit SERIES.csv` finds them (lab/request/fit_request.hpp): the same request, checks, files and
// numbers.
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lab/request/fit_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/field_spelling.hpp"
#include "python/json_values.hpp"
#include "python/loaded_scene.hpp"

namespace fl::python {
namespace {

FitResult fit(const Path& series, const Quantity& gravity, const std::optional<Path>& out,
              const std::optional<Path>& plot, std::optional<std::int64_t> mc, std::uint64_t seed,
              bool through_rig, const std::optional<SceneArgument>& scene, const py::object& set,
              int jobs, const std::optional<std::string>& material,
              const std::optional<Quantity>& temperature) {
  FitRequest request;
  request.series = series.string();
  request.gravity = gravity;
  if (out) request.out = out->string();
  if (plot) request.plot = plot->string();
  request.mc = mc;
  request.seed = seed;
  request.through_rig = through_rig;
  if (scene) request.scene = scene_source_argument(*scene);
  for (const SceneOverride& o : overrides_argument(set))
    request.set.push_back(o.path + "=" + o.value);
  request.jobs = jobs;
  request.material = material;
  request.temperature = temperature;
  FitResult result;
  {
    const py::gil_scoped_release released;
    result = fit_series(request);
  }
  for (const std::string& warning : result.warnings)
    PyErr_WarnEx(PyExc_UserWarning, spelled(warning).c_str(), 1);
  return result;
}

}  // namespace

void bind_fit(py::module_& m) {
  using R = FitResult;
  const auto line = [](auto member) {
    return [member](const R& r) { return r.report.fit.*member; };
  };
  py::class_<R>(m, "FitReport", R"(A spacing series' fit, as `frictionlab fit` reports it (SI).

The thick-plate line T^2 = s l + c through the rows, mu_k and h_c from it with their errors
and correlation, chi^2, and the paper's thin formula's line through the origin for contrast.
json() is the object `frictionlab fit --json` prints (fit.json): every row's residual, the Monte
Carlo (mc=) and the refit through the rig (through_rig=True) are there.)")
      .def_property_readonly("mu_k", line(&ThickPlateFit::mu_k))
      .def_property_readonly("mu_k_err", line(&ThickPlateFit::mu_k_err),
                             "the line's standard error")
      .def_property_readonly("h_c", line(&ThickPlateFit::h_c), "m")
      .def_property_readonly("h_c_err", line(&ThickPlateFit::h_c_err), "m")
      .def_property_readonly("correlation", line(&ThickPlateFit::correlation), "of mu_k and h_c")
      .def_property_readonly("slope", line(&ThickPlateFit::slope), "s [s^2/m]")
      .def_property_readonly("intercept", line(&ThickPlateFit::intercept), "c [s^2]")
      .def_property_readonly("chi2", line(&ThickPlateFit::chi2))
      .def_property_readonly("degrees_of_freedom", line(&ThickPlateFit::degrees_of_freedom))
      .def_property_readonly("chi2_per_dof", line(&ThickPlateFit::chi2_per_dof),
                             "None with two rows")
      .def_property_readonly("mu_k_thin_line", line(&ThickPlateFit::mu_k_thin_line),
                             "the paper's formula: the line through the origin")
      .def_property_readonly("mu_k_thin_line_err", line(&ThickPlateFit::mu_k_thin_line_err))
      .def_property_readonly(
          "gravity", [](const R& r) { return r.report.gravity; }, "m/s^2")
      .def_property_readonly(
          "paper",
          [](const R& r) {
            return r.paper ? python_value(paper_comparison_json(*r.paper)) : py::object(py::none());
          },
          "the paper's value for material= (the dict json()[\"paper\"] holds), or None")
      .def_readonly("written", &R::written, "the files written (fit.csv, fit.json, the plot)")
      .def_property_readonly(
          "plot", [](const R& r) { return r.plot.empty() ? std::nullopt : std::optional(r.plot); },
          "the PNG drawn, or None")
      .def_property_readonly(
          "plot_failure",
          [](const R& r) {
            return r.plot_failure.empty() ? std::nullopt : std::optional(r.plot_failure);
          },
          "why plot= drew nothing, or None")
      .def_property_readonly(
          "rig_failure",
          [](const R& r) {
            return r.rig_failure.empty() ? std::nullopt : std::optional(spelled(r.rig_failure));
          },
          "why the refit through the rig failed (the fit stands; the command exits 3), or None")
      .def(
          "json", [](const R& r) { return python_value(r.json); },
          "The object `frictionlab fit --json` prints, without \"plot\".")
      .def("__repr__", [](const R& r) {
        const ThickPlateFit& f = r.report.fit;
        return "<frictionlab.FitReport mu_k = " +
               (f.mu_k ? py::repr(py::float_(*f.mu_k)).cast<std::string>() : "None") + ", h_c = " +
               (f.h_c ? py::repr(py::float_(*f.h_c)).cast<std::string>() + " m" : "None") +
               " from " + std::to_string(f.rows.size()) + " rows>";
      });

  m.def("fit", &fit, py::arg("series"), py::kw_only(),
        py::arg("gravity") = quantity_input_text(FitRequest{}.gravity), py::arg("out") = py::none(),
        py::arg("plot") = py::none(), py::arg("mc") = py::none(), py::arg("seed") = 1,
        py::arg("through_rig") = false, py::arg("scene") = py::none(), py::arg("set") = py::none(),
        py::arg("jobs") = 0, py::arg("material") = py::none(), py::arg("temperature") = py::none(),
        R"(mu_k and h_c from a spacing series, as `frictionlab fit SERIES.csv`; a FitReport.

series: a CSV whose header names spacing, period, period_err and optionally spacing_err and
  label (values with units: 89 mm, 0.79 s, 5 ms). gravity: g. out: a folder for fit.csv and
  fit.json. plot: a PNG of T^2 against l with the fit ("" for out/fit.png). mc: Monte Carlo
  draws of every row, refitted (seed: the same seed, the same numbers). through_rig: refit
  through simulations of scene (a Scene or a path; default scenes/minimal.yaml) with set's
  overrides, jobs rows at a time (0: every core). material ("lego", a key or name of the
  paper's Table I) and temperature ("77K"; 300 K by default): the paper's value beside the
  fitted mu_k, as paper (json()["paper"] too).
Raises InputError for bad input, as the command exits 2 for it: a series that gives no
friction oscillator (T^2 falling with l) is refused, located in the file.)");
}

}  // namespace fl::python
