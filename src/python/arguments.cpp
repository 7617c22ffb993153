#include "python/arguments.hpp"

#include <cmath>

#include "io/input_error.hpp"

namespace fl::python {

double quantity_argument(const Quantity& value, Dimension dimension, const std::string& name) {
  if (const double* number = std::get_if<double>(&value)) return *number;
  try {
    return parse_quantity(std::get<std::string>(value), dimension, name);
  } catch (const UnitError& e) {
    throw InputError(SourceLocation{}, e.what());
  }
}

std::optional<double> optional_quantity(const std::optional<Quantity>& value, Dimension dimension,
                                        const std::string& name) {
  if (!value) return std::nullopt;
  return quantity_argument(*value, dimension, name);
}

std::string quantity_text(const Quantity& value) {
  if (const std::string* text = std::get_if<std::string>(&value)) return *text;
  return py::repr(py::float_(std::get<double>(value))).cast<std::string>();
}

std::string override_text(py::handle value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::float_>(value) && !std::isfinite(value.cast<double>()))
    return py::repr(value).cast<std::string>();  // "nan", "inf": refused by the loader as text
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

}  // namespace fl::python
