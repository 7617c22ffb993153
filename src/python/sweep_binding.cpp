// frictionlab.sweep: every point of a sweep file run in parallel on local threads, resumable, as
// `frictionlab sweep SWEEP.yaml` runs it (lab/sweep/sweep_run.hpp): the same folder of results, and
// its rows returned as columns.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lab/request/sweep_request.hpp"
#include "lab/sweep/sweep_results.hpp"
#include "lab/sweep/sweep_run.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/lab_data.hpp"

namespace fl::python {
namespace {

using json = nlohmann::json;

// One column of the rows: numbers as a NumPy masked array (masked where the row has no value:
// null in results.json; int64 when every value is a whole number, else float64 with NaN under
// the mask), booleans as a masked bool array, anything else as a list (None for null). A column
// with no value in any row is a wholly masked float64 array.
py::object column(const std::vector<const json*>& values) {
  bool numbers = true, integers = true, booleans = true;
  for (const json* v : values) {
    if (v->is_null()) continue;
    numbers = numbers && v->is_number();
    integers = integers && v->is_number_integer();
    booleans = booleans && v->is_boolean();
  }
  const auto n = static_cast<py::ssize_t>(values.size());
  py::array_t<bool> mask(n);
  bool any_null = false;
  for (py::ssize_t i = 0; i < n; ++i) {
    mask.mutable_at(i) = values[i]->is_null();
    any_null = any_null || values[i]->is_null();
  }
  const py::object masked = py::module_::import("numpy").attr("ma").attr("MaskedArray");
  if (booleans && !numbers) {
    py::array_t<bool> data(n);
    for (py::ssize_t i = 0; i < n; ++i)
      data.mutable_at(i) = !values[i]->is_null() && values[i]->get<bool>();
    return masked(data, py::arg("mask") = mask);
  }
  if (numbers && integers && !any_null) {
    py::array_t<std::int64_t> data(n);
    for (py::ssize_t i = 0; i < n; ++i) data.mutable_at(i) = values[i]->get<std::int64_t>();
    return masked(data, py::arg("mask") = mask);
  }
  if (numbers) {
    py::array_t<double> data(n);
    for (py::ssize_t i = 0; i < n; ++i)
      data.mutable_at(i) = values[i]->is_null() ? std::numeric_limits<double>::quiet_NaN()
                                                : values[i]->get<double>();
    return masked(data, py::arg("mask") = mask);
  }
  py::list out;
  for (const json* v : values) out.append(python_value(*v));
  return out;
}

py::dict sweep(const Path& file, std::optional<int> jobs, const std::optional<Path>& out,
               bool fresh, const std::optional<std::string>& shard, bool plot,
               const py::object& progress, const std::optional<Path>& assets,
               const std::optional<Quantity>& accuracy) {
  SweepRequest request;
  request.file = file.string();
  request.jobs = jobs;
  if (out) request.out = out->string();
  request.fresh = fresh;
  if (shard) request.shard = *shard;
  request.plot = plot;
  if (assets) request.assets = assets->string();
  request.accuracy = accuracy;
  const PreparedSweep prepared = prepare_sweep(request);
  const SweepRunOptions& options = prepared.options;
  std::atomic<bool> stop{false};
  // Called on this thread while the points run: Ctrl-C (or an error in the callback) stops
  // handing out points; the running ones finish and are kept, so the same call resumes.
  std::optional<py::error_already_set> interrupted;
  const auto on_progress = [&](const SweepProgress& p) {
    const py::gil_scoped_acquire acquired;
    if (interrupted) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none())
        progress(py::dict(py::arg("total") = p.total, py::arg("done") = p.done,
                          py::arg("resumed") = p.resumed, py::arg("failed") = p.failed,
                          py::arg("invalid") = p.invalid, py::arg("elapsed_s") = p.elapsed_s));
    } catch (py::error_already_set& e) {
      interrupted = std::move(e);
      stop = true;
    }
  };
  SweepResult result;
  {
    const py::gil_scoped_release released;
    result = execute_sweep(prepared, &stop, on_progress);
  }
  if (interrupted) throw *interrupted;
  if (!result.plot_failure.empty())
    PyErr_WarnEx(PyExc_UserWarning, ("no plots: " + result.plot_failure).c_str(), 1);

  const SweepStore store = SweepStore::open(options.out_dir);
  const std::map<std::size_t, PointResult> points = store.load_points();
  const std::vector<std::string> names = sweep_result_columns(store.plan());
  // index, then one column per axis (the point's label for it, in the row's params), then the
  // results' fixed columns, as results.csv has them.
  const std::size_t axes = store.plan().at("axes").size();
  py::dict columns;
  for (std::size_t c = 0; c < names.size(); ++c) {
    static const json kNull;
    std::vector<const json*> values;
    values.reserve(points.size());
    for (const auto& [index, point] : points) {
      const json& cells = c >= 1 && c <= axes ? point.row.at("params") : point.row;
      const auto it = cells.find(names[c]);
      values.push_back(it == cells.end() ? &kNull : &*it);
    }
    columns[py::str(names[c])] = column(values);
  }
  return columns;
}

py::object merge(const std::vector<Path>& dirs, const std::optional<Path>& out, bool plot) {
  MergeRequest r;
  for (const Path& d : dirs) r.dirs.push_back(d.string());
  if (out) r.out = out->string();
  r.plot = plot;
  MergeResult result;
  {
    const py::gil_scoped_release released;
    result = merge_shards(r);
  }
  if (!result.plot_failure.empty())
    PyErr_WarnEx(PyExc_UserWarning, ("no plots: " + result.plot_failure).c_str(), 1);
  return python_value(result.json());
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("merge", &merge, py::arg("dirs"), py::kw_only(), py::arg("out") = py::none(),
        py::arg("plot") = false,
        R"(Joins the shards of a sweep (the folders runs with shard="K/N" wrote), as
`frictionlab merge`: into out (default the first folder), results.csv and sweep.json as the
whole sweep run in one go would write them. Returns the object `frictionlab merge --json`
prints (out, points, status, files, plots); a plot that fails warns. Raises InputError for a
folder that is no sweep's or shards of different sweeps.)");
  m.def("sweep", &sweep, py::arg("file"), py::kw_only(), py::arg("jobs") = py::none(),
        py::arg("out") = py::none(), py::arg("fresh") = false, py::arg("shard") = py::none(),
        py::arg("plot") = false, py::arg("progress") = py::none(), py::arg("assets") = py::none(),
        py::arg("accuracy") = py::none(),
        R"(Runs every point of a sweep file (docs/sweep-format.md), as `frictionlab sweep`.

jobs: worker threads (default: every core). out: the sweep's folder (default
out/sweep/NAME, as the command's), where plan.json, points/, results.csv and sweep.json are
written; points found done there are not run again (fresh=True discards them). shard: "K/N"
runs the points whose index % N == K-1. accuracy: run each point at the largest step
whose predicted period error stays within it ("0.01%", over the file's accuracy:). plot: draw the results' plots into out, as
`frictionlab sweep --plot` (a plot that fails warns; the results stand). progress: called as points finish with a dict
(total, done, resumed, failed, invalid, elapsed_s: failed, a guard stopped the run;
invalid, the scene refused the point's values). Ctrl-C stops handing out points; the running
ones finish and are kept, and KeyboardInterrupt is raised. Bad input (jobs below 1, a shard
that is not K/N, an out that cannot be written) raises InputError before any point runs.

Returns the rows of every finished point in the folder, in point order, as columns
{name: values} in results.csv's order: numbers as NumPy masked arrays (masked where the
point has no value, e.g. no period outside a harmonic oscillation or for a failed point;
int64 when every value is a whole number, else float64 with NaN under the mask; a column
with no value at all is wholly masked), text as lists (None where there is none). The axes'
columns hold each point's label ("50 mm", "lego"). The status column says ok, invalid or
failed.)");
}

}  // namespace fl::python
