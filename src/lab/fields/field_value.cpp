#include "lab/fields/field_value.hpp"

#include <type_traits>

#include "io/json_value.hpp"
#include "text/utf8.hpp"

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

FieldValue escaped_text(const std::string& text) {
  return FieldValue::text(escape_invalid_utf8(text));
}

FieldValue escaped_text_or_none(const std::string& text) {
  return text.empty() ? FieldValue() : escaped_text(text);
}

}  // namespace fl
