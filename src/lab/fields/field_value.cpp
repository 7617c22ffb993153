#include "lab/fields/field_value.hpp"

#include <type_traits>

#include "io/json_value.hpp"

namespace fl {

using json = nlohmann::json;

json FieldValue::json() const {
  return std::visit(
      [](const auto& v) -> nlohmann::json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return nullptr;
        else if constexpr (std::is_same_v<T, double>)
          return json_or_null(v);
        else
          return nlohmann::json(v);
      },
      value_);
}

}  // namespace fl
