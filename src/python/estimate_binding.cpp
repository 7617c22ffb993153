// frictionlab.estimate and estimate_file: T +- dT and mu_k +- d mu_k from a Hall signal by the
// rig's own estimator (src/estimator/period_estimator.h), as `frictionlab estimate LOG` finds
// them (lab/logs/log_estimate.hpp): from arrays of times and ADC values, or from a log file.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/estimate_fields.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/request/estimate_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/field_spelling.hpp"
#include "python/json_values.hpp"
#include "python/record_arrays.hpp"

namespace fl::python {
namespace {

// The log and what the estimator made of it.
struct Estimate {
  HallLog log;
  LogEstimate estimate;
  std::optional<PaperComparison> paper;  // the paper's value for the log's material, when named
};

// The request's answer as the module's Estimate; the GIL released while the estimator runs.
Estimate estimate_of(const EstimateRequest& request) {
  const PreparedEstimate prepared = prepare_estimate(request);
  for (const std::string& warning : prepared.warnings)
    PyErr_WarnEx(PyExc_UserWarning, spelled(warning).c_str(), 1);
  OneLogEstimate result;
  {
    const py::gil_scoped_release released;
    result = estimate_one_log(prepared);
  }
  for (const std::string& warning : result.warnings)
    PyErr_WarnEx(PyExc_UserWarning, spelled(warning).c_str(), 1);
  return Estimate{std::move(result.log), std::move(result.estimate), std::move(result.paper)};
}

// The arguments both functions share, as the request's fields.
EstimateRequest request_of(const Quantity& spacing, const Quantity& spacing_err,
                           const Quantity& gravity, const std::string& geometry) {
  EstimateRequest r;
  r.spacing = spacing;
  r.spacing_err = spacing_err;
  r.gravity = gravity;
  r.geometry = geometry;
  return r;
}

using Samples = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<double> doubles(const Samples& a, const char* name) {
  if (a.ndim() != 1)
    throw py::type_error(std::string(name) + ": expected a one-dimensional array of numbers");
  return std::vector<double>(a.data(), a.data() + a.size());
}

py::array pulses_array(std::vector<EstimatedPulse> pulses) {
  return rows_array(std::move(pulses), {{"time_s", "<f8", offsetof(EstimatedPulse, time)},
                                        {"rise_s", "<f8", offsetof(EstimatedPulse, rise)},
                                        {"fall_s", "<f8", offsetof(EstimatedPulse, fall)},
                                        {"peak", "<i4", offsetof(EstimatedPulse, peak)},
                                        {"distorted", "?", offsetof(EstimatedPulse, distorted)}});
}

}  // namespace

void bind_estimate(py::module_& m) {
  using E = Estimate;
  py::class_<E> estimate(m, "Estimate", R"(What the rig's estimator found in a Hall signal (SI).

The period T +- dT (dT the standard deviation of the accepted periods) and mu_k +- d mu_k
through the paper's formula, as `frictionlab estimate` reports them; the estimator holds them
in single precision, as the rig's Arduino does. json() is the object
`frictionlab estimate --json` prints (without "plot").)");
  // Every plain value from the one declaration of an estimate's keys (lab/logs/estimate_fields).
  for (const EstimateField& f : estimate_fields()) {
    if (f.python == nullptr) continue;
    const auto get = f.get;
    estimate.def_property_readonly(
        f.python,
        [get](const E& e) {
          return python_field(get({e.log, e.estimate}));
        },
        field_doc(f.unit, f.meaning, f.null_when).c_str());
  }
  estimate
      .def_property_readonly(
          "pulses", [](const E& e) { return pulses_array(e.estimate.pulses); },
          "structured array, shape (pulses,): time_s (the turning point, for one pulse per\n"
          "period), rise_s and fall_s (the timing level's crossings), peak (counts), distorted")
      .def_property_readonly(
          "periods",
          [](const E& e) {
            return periods_array(std::vector<EstimatedPeriod>(e.estimate.periods));
          },
          "structured array, shape (periods,): start_s, end_s, period_s and status (0 "
          "accepted,\n1 an outlier, 2 at a broken turning point)")
      .def(
          "json",
          [](const E& e) {
            nlohmann::json j = log_estimate_json(e.log, e.estimate);
            j["paper"] = e.paper ? paper_comparison_json(*e.paper) : nlohmann::json(nullptr);
            return python_value(j);
          },
          "The object `frictionlab estimate --json` prints, without \"plot\" and "
          "\"monte_carlo\".")
      .def("__repr__", [](const E& e) {
        const fl_estimator::Stats& s = e.estimate.stats;
        return "<frictionlab.Estimate T = " +
               py::repr(py::float_(static_cast<double>(s.period_s))).cast<std::string>() +
               " s from " + std::to_string(s.periods_used) + " periods, mu_k = " +
               py::repr(py::float_(static_cast<double>(s.mu_k))).cast<std::string>() + ">";
      });

  // The defaults are the request's (lab/request/estimate_request.hpp), shown as text.
  const EstimateRequest d;
  m.def(
      "estimate",
      [](const Samples& t, const Samples& adc, const Quantity& spacing, const Quantity& spacing_err,
         const Quantity& gravity, const std::string& geometry, const std::string& name) {
        EstimateRequest r = request_of(spacing, spacing_err, gravity, geometry);
        r.samples = hall_log_from_samples(doubles(t, "t"), doubles(adc, "adc"), name);
        return estimate_of(r);
      },
      py::arg("t"), py::arg("adc"), py::kw_only(),
      py::arg("spacing") = quantity_input_text(d.spacing),
      py::arg("spacing_err") = quantity_input_text(d.spacing_err),
      py::arg("gravity") = quantity_input_text(d.gravity), py::arg("geometry") = d.geometry,
      py::arg("name") = "samples",
      R"(T +- dT and mu_k +- d mu_k from a Hall signal, by the rig's own estimator.

t: sample times [s], increasing (e.g. result.hall["t_us"] * 1e-6); adc: the ADC values
[counts, 0 to 65535], one per time. spacing, spacing_err, gravity: l, dl and g for mu_k
(text with units or SI numbers). geometry: pulses per period, "auto" (recognised),
"one" or "pair". Raises InputError, as `frictionlab estimate` fails, when the signal gives no
T +- dT (saying what it found); its line is the 1-based sample index, `name` its file.)");
  m.def(
      "estimate_file",
      [](const Path& path, const Quantity& spacing, const Quantity& spacing_err,
         const Quantity& gravity, const std::string& geometry, const std::string& columns,
         const std::optional<Quantity>& rate, const std::string& time_unit,
         const std::optional<std::string>& material, const std::optional<Quantity>& temperature,
         const std::optional<Quantity>& h_c) {
        EstimateRequest r = request_of(spacing, spacing_err, gravity, geometry);
        r.logs = {path.string()};
        r.h_c = h_c;
        r.columns = columns;
        r.rate = rate;
        r.time_unit = time_unit;
        r.material = material;
        r.temperature = temperature;
        return estimate_of(r);
      },
      py::arg("path"), py::kw_only(), py::arg("spacing") = quantity_input_text(d.spacing),
      py::arg("spacing_err") = quantity_input_text(d.spacing_err),
      py::arg("gravity") = quantity_input_text(d.gravity), py::arg("geometry") = d.geometry,
      py::arg("columns") = "", py::arg("rate") = py::none(), py::arg("time_unit") = "",
      py::arg("material") = py::none(), py::arg("temperature") = py::none(),
      py::arg("h_c") = py::none(),
      R"(T +- dT and mu_k +- d mu_k from a Hall-sensor log, as `frictionlab estimate LOG`.

The log: the rig firmware's serial capture or any CSV of time and ADC value ("t_us,adc",
"t_s,adc", "time,value"), e.g. the hall.csv of run(..., out=...); or another instrument's
file, recognised by what it holds (a phone's phyphox CSV, Tracker's data, a position-time
table: `instrument` and `channel` say what was read). h_c ("3.6 mm"), the plate's centre of
mass above the rollers' contact line, gives mu_k_thick through the thick formula. Arguments
as estimate; the log's sidecar (the log's name with .yaml: spacing, spacing_err, gravity,
geometry) is read over them, as the command reads it. columns ("t_us,adc", "_,t_ms,adc"), rate ("1kHz") and
time_unit ("us", "ms", "s") say how to read a log whose header does not, as the command's
--columns, --rate and --time-unit. material ("lego", a key or name of the paper's Table I) and
temperature ("77K"; 300 K by default), or the sidecar's, put the paper's value for it beside
the result: json()["paper"], with the difference in combined standard errors. Raises InputError
located in the log (file:line:column).)");
}

}  // namespace fl::python
