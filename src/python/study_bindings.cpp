// frictionlab.compare, accuracy and stability: the comparison with measurements and the two
// studies of the numerics, as `frictionlab compare`, `accuracy` and `stability` ask for them
// (lab/request/compare_request.hpp, study_requests.hpp): the same requests, checks and files;
// each returns the object the command's --json prints.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "lab/request/compare_request.hpp"
#include "lab/request/study_requests.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/interrupt_watch.hpp"
#include "python/json_values.hpp"
#include "python/loaded_scene.hpp"

namespace fl::python {
namespace {

std::vector<std::string> set_texts(const py::object& set) {
  std::vector<std::string> out;
  for (const SceneOverride& o : overrides_argument(set)) out.push_back(o.path + "=" + o.value);
  return out;
}

py::object compare(const std::optional<Path>& measured, const std::optional<Path>& log,
                   const std::optional<Path>& scene, const py::object& set,
                   const std::optional<Quantity>& duration, int jobs,
                   const std::optional<Path>& out, bool plot, bool refit,
                   const std::string& geometry, const std::string& columns,
                   const std::optional<Quantity>& rate, const std::string& time_unit,
                   const std::optional<Path>& assets, const std::optional<std::string>& material,
                   const std::optional<Quantity>& temperature) {
  CompareRequest r;
  if (measured) r.measured = measured->string();
  if (log) r.log = log->string();
  if (scene) r.scene = scene->string();
  r.set = set_texts(set);
  r.duration = duration;
  r.jobs = jobs;
  if (out) r.out = out->string();
  r.plot = plot;
  r.refit = refit;
  r.geometry = geometry;
  r.columns = columns;
  r.rate = rate;
  r.time_unit = time_unit;
  if (assets) r.assets = assets->string();
  r.material = material;
  r.temperature = temperature;
  CompareRequestResult result;
  InterruptWatch watch;
  {
    const py::gil_scoped_release released;
    result = compare_measurements(r, {}, watch.control());
  }
  // Ctrl-C: the rows done are written; Python hears KeyboardInterrupt.
  watch.raise();
  return python_value(result.json);
}

py::object accuracy(const SceneArgument& scene, const py::object& set, int periods,
                    const std::optional<Path>& out, bool plot) {
  AccuracyRequest r;
  r.scene = scene_source_argument(scene);
  r.set = set_texts(set);
  r.periods = periods;
  if (out) r.out = out->string();
  r.plot = plot;
  AccuracyResult result;
  InterruptWatch watch;
  {
    const py::gil_scoped_release released;
    result = study_accuracy(r, watch.control());
  }
  watch.raise();
  return python_value(result.json());
}

py::object stability(const std::optional<Path>& dir, const std::string& only,
                     std::optional<int> jobs, const std::optional<Path>& out,
                     const std::optional<Path>& assets) {
  StabilityRequest r;
  if (dir) r.dir = dir->string();
  r.only = only;
  r.jobs = jobs;
  if (out) r.out = out->string();
  if (assets) r.assets = assets->string();
  StabilityResult result;
  InterruptWatch watch;
  {
    const py::gil_scoped_release released;
    result = study_stability(r, watch.control());
  }
  watch.raise();
  return python_value(result.json());
}

}  // namespace

void bind_studies(py::module_& m) {
  const CompareRequest c;
  m.def("compare", &compare, py::kw_only(), py::arg("measured") = py::none(),
        py::arg("log") = py::none(), py::arg("scene") = py::none(), py::arg("set") = py::none(),
        py::arg("duration") = py::none(), py::arg("jobs") = 0, py::arg("out") = c.out,
        py::arg("plot") = false, py::arg("refit") = true, py::arg("geometry") = "",
        py::arg("columns") = "", py::arg("rate") = py::none(), py::arg("time_unit") = "",
        py::arg("assets") = py::none(), py::arg("material") = py::none(),
        py::arg("temperature") = py::none(),
        R"(Simulates every row of measurements (the paper's Table I by default) and refits mu_k
through the rig, or holds one Hall log (log=) against its simulation, as `frictionlab compare`.

Returns the object `frictionlab compare --json` prints (compare.json or compare-log.json, also
written to out). A row of your own measurements that gives no result is in the rows, with its
status and reason (the command exits 3 for it). With log=, material and temperature (or the
log's sidecar) put the paper's value beside the refitted mu_k, as "paper". Raises InputError for
bad input. Ctrl-C starts no more simulations: the rows done are written (the others marked
"interrupted") and KeyboardInterrupt is raised.)");
  const AccuracyRequest a;
  m.def("accuracy", &accuracy, py::arg("scene"), py::kw_only(), py::arg("set") = py::none(),
        py::arg("periods") = a.periods, py::arg("out") = a.out, py::arg("plot") = false,
        R"(The work-precision study of a scene (period error against run time), as
`frictionlab accuracy`; returns accuracy.json's object (written to out with accuracy.csv). Ctrl-C
keeps the points finished (written) and raises KeyboardInterrupt.)");
  m.def("stability", &stability, py::kw_only(), py::arg("dir") = py::none(), py::arg("only") = "",
        py::arg("jobs") = py::none(), py::arg("out") = py::none(), py::arg("assets") = py::none(),
        R"(The catalogue of stiff and extreme cases (scenes/extreme), each held to the regime
theory expects, as `frictionlab stability`; returns {"cases": [...], "unexpected": N}. Ctrl-C
starts no more cases, finishes those running (written to out) and raises KeyboardInterrupt.)");
}

}  // namespace fl::python
