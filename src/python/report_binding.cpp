// frictionlab.report: the lab report a student hands in, as `frictionlab report` writes it
// (lab/request/report_request.hpp): runs' folders and measurement files in, one HTML file out.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "lab/request/report_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"

namespace fl::python {

void bind_report(py::module_& m) {
  m.def(
      "report",
      [](const std::vector<Path>& inputs, const Path& out, const std::string& student,
         const std::vector<std::tuple<int, double, std::optional<double>>>& stopwatch,
         const Quantity& spacing, const std::optional<std::string>& material,
         const std::optional<Quantity>& temperature, const std::optional<Path>& assets,
         const std::string& language) {
        ReportRequest r;
        for (const Path& input : inputs) r.inputs.push_back(input.string());
        r.out = out.string();
        r.student = student;
        for (const auto& [periods, wall_s, simulated_s] : stopwatch)
          r.stopwatch.push_back({periods, wall_s, simulated_s});
        r.measurement.spacing = spacing;
        r.measurement.material = material;
        if (temperature) r.measurement.temperature = *temperature;
        if (assets) r.assets = assets->string();
        r.lab_version = "frictionlab " FRICTIONLAB_VERSION;
        r.language = language;
        return python_value(make_report(r).json());
      },
      py::arg("inputs"), py::kw_only(), py::arg("out"), py::arg("student") = "",
      py::arg("stopwatch") = std::vector<std::tuple<int, double, std::optional<double>>>{},
      py::arg("spacing") = "89 mm", py::arg("material") = py::none(),
      py::arg("temperature") = py::none(), py::arg("assets") = py::none(),
      py::arg("language") = "en",
      R"(Writes the lab report a student hands in, as `frictionlab report` does: one HTML file
(`out`) that prints to PDF, with each input's set-up, data (figures as SVG, the periods' table),
T +- dT and mu_k +- d mu_k with where each uncertainty comes from, and the comparison with the
paper's Table I and with theory. An input is a folder `run(out=...)` wrote (its summary.json) or
a measurement file (a Hall log, a phone's file, a video), read as estimate_file reads it with
`spacing` and `material`. stopwatch: (periods, wall seconds, simulated seconds or None) for each
timing by hand. language: "en", "fr" (a catalogue of the lab's data). Returns what the report says as a dict (written, parts: title, period_s, mu_k,
...). Bad input raises InputError.)");
}

}  // namespace fl::python
