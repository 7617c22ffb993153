// Python arguments read as the frictionlab command reads its options: a quantity is text with
// units ("89mm", "1600rpm") or a plain number in SI; a scene override's value is text as given
// (YAML, as after --set key=) or any other value written as JSON, which YAML reads alike
// (0.3, True, [], {"x": "95mm"}); a path is str or os.PathLike.
#pragma once

#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "core/units.hpp"

namespace fl::python {

namespace py = pybind11;

// Throws InputError "error: spacing: expected a length ..." naming the argument.
double quantity_argument(py::handle value, Dimension dimension, const std::string& name);
std::optional<double> optional_quantity(py::handle value, Dimension dimension,
                                        const std::string& name);

std::string override_text(py::handle value);

std::string path_argument(py::handle value);
std::optional<std::string> optional_path(py::handle value);

}  // namespace fl::python
