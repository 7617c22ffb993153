#include "python/json_values.hpp"

#include <string>
#include <type_traits>
#include <variant>

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

py::object python_field(const FieldValue& field) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return py::none();
        else if constexpr (std::is_same_v<T, nlohmann::json>)
          return python_value(v);
        else
          return py::cast(v);
      },
      field.value());
}

std::string field_doc(const char* unit, const char* meaning, const char* null_when) {
  std::string doc = std::string(unit).empty() ? "" : std::string(unit) + ", ";
  doc += meaning;
  if (null_when != nullptr) doc += "; None when " + std::string(null_when);
  return doc;
}

}  // namespace fl::python
