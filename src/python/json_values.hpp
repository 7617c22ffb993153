// JSON values (the lab's outputs: a run's summary, an estimate, the analytic report, a sweep's
// rows) as Python values: objects as dicts, arrays as lists, null as None, numbers exactly.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace fl::python {

namespace py = pybind11;

py::object python_value(const nlohmann::json& value);

}  // namespace fl::python
