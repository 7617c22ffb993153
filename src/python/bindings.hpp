// The frictionlab Python module, one part of the lab per file: each bind_* adds its functions and
// classes to the module (module.cpp calls them in the order their types are needed).
#pragma once

#include <pybind11/pybind11.h>

namespace fl::python {

namespace py = pybind11;

void bind_input_error(py::module_& m);   // InputError and the C++ errors it stands for
void bind_common_types(py::module_& m);  // Regime, PeriodSource, Measured
void bind_scene(py::module_& m);         // Scene, load_scene, parse_scene
void bind_run(py::module_& m);           // RunSummary, RunResult, run
void bind_estimate(py::module_& m);      // Estimate, estimate, estimate_file
void bind_analytic(py::module_& m);      // AnalyticReport, analytic
void bind_paper_table(py::module_& m);   // PaperTable, paper_table
void bind_sweep(py::module_& m);         // sweep
void bind_fit(py::module_& m);           // fit
void bind_studies(py::module_& m);       // compare, accuracy, stability
void bind_track(py::module_& m);         // track
void bind_report(py::module_& m);        // report

}  // namespace fl::python
