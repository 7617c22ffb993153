// What every request's validation shares: a field's value as a front end gives it (text with
// units, or a plain number in SI), and a collector that reads the fields of a request and gathers
// every problem by field before anything runs, so that a front end can show each beside its own
// control. The problems name fields ("spacing", "video.size"), never a front end's spelling of
// them (io/field_ref.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/plausible_range.hpp"
#include "core/units.hpp"
#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {

// A quantity as a front end gives it: "89 mm" (units as in scene files), or a number in SI.
using QuantityInput = std::variant<std::string, double>;

// The text a quantity stands for ("89 mm", or the number's shortest form).
std::string quantity_input_text(const QuantityInput& value);

// One problem with one field: "spacing", "expected a finite positive length, found -3 mm; ...".
struct FieldProblem {
  std::string field;
  std::string message;               // what was expected, what was found, what to do
  std::optional<std::string> value;  // the value the message quotes as the field's, if any
  // The message as the catalogues say it (text/said.hpp); nullopt for one in English only.
  std::optional<Said> said = std::nullopt;
};

// Bad input in a request: every problem found, by field. what() is the first problem's located
// message (and one line per further problem); where() is the first problem's field.
class RequestError : public InputError {
 public:
  explicit RequestError(std::vector<FieldProblem> problems);
  const std::vector<FieldProblem>& problems() const { return problems_; }

 private:
  std::vector<FieldProblem> problems_;
};

// Reads a request's fields and gathers their problems. A field that cannot be read gives NaN (or
// nullopt) and a problem; the validation goes on, and throw_if_any() ends it.
class FieldChecks {
 public:
  // The quantity in SI; a plain number given as text is SI too.
  double quantity(const QuantityInput& value, Dimension dimension, std::string_view field);
  std::optional<double> quantity(const std::optional<QuantityInput>& value, Dimension dimension,
                                 std::string_view field);
  // The same, and refused unless finite and positive (not_negative: finite and 0 or more);
  // `what` says what the field is ("the roller spacing").
  double positive(const QuantityInput& value, Dimension dimension, std::string_view field,
                  std::string_view what);
  double not_negative(const QuantityInput& value, Dimension dimension, std::string_view field,
                      std::string_view what);

  // Refuses a value beyond the quantity's range on any bench (core/plausible_range.hpp): a slip
  // of the unit or the keyboard, never computed with. `input` is the field's value as given: a
  // plain number read as SI is said to be one (and its warning is then this problem).
  void plausible(double value, const PlausibleRange& range, std::string_view field,
                 const QuantityInput& input);
  void plausible(const std::optional<double>& value, const PlausibleRange& range,
                 std::string_view field, const std::optional<QuantityInput>& input);

  void problem(std::string_view field, std::string message);
  void problem(std::string_view field, std::string value, std::string message);
  void problem(std::string_view field, const Said& message);
  bool has(std::string_view field) const;
  bool ok() const { return problems_.empty(); }

  // Warnings for the front end to show: a plain number of 2 or more read as metres.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Throws RequestError with every problem found, if any.
  void throw_if_any() const;

 private:
  std::vector<FieldProblem> problems_;
  std::vector<std::string> warnings_;
  std::vector<std::string> warning_fields_;  // the field each warning is about
};

}  // namespace fl
