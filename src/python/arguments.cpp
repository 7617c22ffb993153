#include "python/arguments.hpp"

#include <cmath>

#include "io/input_error.hpp"

namespace fl::python {

double quantity_argument(py::handle value, Dimension dimension, const std::string& name) {
  if (py::isinstance<py::str>(value)) {
    try {
      return parse_quantity(value.cast<std::string>(), dimension, name);
    } catch (const UnitError& e) {
      throw InputError(SourceLocation{}, e.what());
    }
  }
  if (py::isinstance<py::bool_>(value) || !PyNumber_Check(value.ptr()))
    throw InputError(SourceLocation{}, name + ": expected a " +
                                           std::string(dimension_name(dimension)) +
                                           " (a number in SI or text with units), found " +
                                           py::repr(value).cast<std::string>());
  return value.cast<double>();
}

std::optional<double> optional_quantity(py::handle value, Dimension dimension,
                                        const std::string& name) {
  if (value.is_none()) return std::nullopt;
  return quantity_argument(value, dimension, name);
}

std::string override_text(py::handle value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::float_>(value) && !std::isfinite(value.cast<double>()))
    return py::repr(value).cast<std::string>();  // "nan", "inf": refused by the loader as text
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

std::string path_argument(py::handle value) {
  return py::module_::import("os").attr("fspath")(value).cast<std::string>();
}

std::optional<std::string> optional_path(py::handle value) {
  if (value.is_none()) return std::nullopt;
  return path_argument(value);
}

}  // namespace fl::python
