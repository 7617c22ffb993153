// A result's field value as the lab holds it, and what kind of value a field has: the pieces the
// declarations of result fields share (lab/run/summary_fields.hpp, a run's; lab/logs/
// log_table_fields.hpp, a log table's row).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

namespace fl {

// A field's value as the lab holds it: none (the run did not measure it), a number, a whole
// number, a yes or no, a text, or a nested object (JSON).
class FieldValue {
 public:
  using Value = std::variant<std::monostate, double, std::int64_t, std::uint64_t, bool, std::string,
                             nlohmann::json>;
  FieldValue() = default;
  static FieldValue number(double v) { return FieldValue(v); }
  static FieldValue number(const std::optional<double>& v) {
    return v ? FieldValue(*v) : FieldValue();
  }
  static FieldValue whole(std::int64_t v) { return FieldValue(v); }
  static FieldValue whole(std::uint64_t v) { return FieldValue(v); }
  static FieldValue whole(const std::optional<int>& v) {
    return v ? FieldValue(std::int64_t{*v}) : FieldValue();
  }
  static FieldValue flag(bool v) { return FieldValue(v); }
  static FieldValue text(std::string v) { return FieldValue(std::move(v)); }
  static FieldValue text(const char* v) { return FieldValue(std::string(v)); }
  static FieldValue text(const std::optional<std::string>& v) {
    return v ? FieldValue(*v) : FieldValue();
  }
  // A nested object; JSON null for none.
  static FieldValue object(nlohmann::json v) {
    return v.is_null() ? FieldValue() : FieldValue(std::move(v));
  }

  const Value& value() const { return value_; }
  bool is_none() const { return std::holds_alternative<std::monostate>(value_); }
  // The JSON value: null for none, and for a number that is not finite (JSON holds none).
  nlohmann::json json() const;

 private:
  template <typename T>
  explicit FieldValue(T v) : value_(std::move(v)) {}
  Value value_;
};

// What a field's values are, for the typed front ends (the .pyi stub, the page's TypeScript).
enum class FieldType {
  kNumber,   // a real number (float; JSON number)
  kInteger,  // a whole number
  kText,     // a text
  kFlag,     // yes or no
  kObject,   // a nested object (its keys in `meaning`)
};

// A text as read from outside (a file's name, a header's words, a label), bytes that are not
// UTF-8 escaped (text/utf8.hpp): JSON's strings are UTF-8. The second is none when the text is
// empty.
FieldValue escaped_text(const std::string& text);
FieldValue escaped_text_or_none(const std::string& text);

}  // namespace fl
