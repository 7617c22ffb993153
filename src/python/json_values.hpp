// JSON values (the lab's outputs: a run's summary, an estimate, the analytic report, a sweep's
// rows) as Python values: objects as dicts, arrays as lists, null as None, numbers exactly.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>

#include "lab/fields/field_value.hpp"

namespace fl::python {

namespace py = pybind11;

py::object python_value(const nlohmann::json& value);

// A declared field's value (lab/fields/field_value.hpp) as Python holds it: None, a float
// (infinity kept), an int, a bool, a str, or a dict or list for a nested value.
py::object python_field(const FieldValue& field);

// A declared field's docstring: its unit, what it means, when it is None.
std::string field_doc(const char* unit, const char* meaning, const char* null_when);

}  // namespace fl::python
