// Python arguments read as the frictionlab command reads its options: a quantity is text with
// units ("89mm", "1600rpm") or a plain number in SI; a scene override's value is text as given
// (YAML, as after --set key=) or any other value written as JSON, which YAML reads alike
// (0.3, True, [], {"x": "95mm"}); a path is str or os.PathLike.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "core/units.hpp"

namespace fl::python {

namespace py = pybind11;

// A quantity as Python gives it: Union[str, float] in a signature.
using Quantity = std::variant<std::string, double>;
using Path = std::filesystem::path;

// Throws InputError "error: spacing: expected a length ..." naming the argument.
double quantity_argument(const Quantity& value, Dimension dimension, const std::string& name);
std::optional<double> optional_quantity(const std::optional<Quantity>& value, Dimension dimension,
                                        const std::string& name);

// The text a quantity stands for after `--set key=`: the text, or the number's shortest form.
std::string quantity_text(const Quantity& value);

std::string override_text(py::handle value);

}  // namespace fl::python
