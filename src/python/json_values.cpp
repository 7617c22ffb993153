#include "python/json_values.hpp"

#include <string>

namespace fl::python {

py::object python_value(const nlohmann::json& value) {
  using Type = nlohmann::json::value_t;
  switch (value.type()) {
    case Type::null:
    case Type::discarded:
      return py::none();
    case Type::boolean:
      return py::bool_(value.get<bool>());
    case Type::number_integer:
      return py::int_(value.get<std::int64_t>());
    case Type::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case Type::number_float:
      return py::float_(value.get<double>());
    case Type::string:
      return py::str(value.get_ref<const std::string&>());
    case Type::array: {
      py::list out;
      for (const nlohmann::json& item : value) out.append(python_value(item));
      return out;
    }
    case Type::object: {
      py::dict out;
      for (const auto& [key, item] : value.items()) out[py::str(key)] = python_value(item);
      return out;
    }
    case Type::binary:
      break;
  }
  throw py::type_error("a JSON value of a type Python has no value for");
}

}  // namespace fl::python
