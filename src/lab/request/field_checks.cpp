#include "lab/request/field_checks.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "io/field_ref.hpp"

namespace fl {
namespace {

constexpr double kUnread = std::numeric_limits<double>::quiet_NaN();

// The first problem's location: its field, with the value the message quotes.
SourceLocation location_of(const FieldProblem& p) {
  return p.value ? SourceLocation::of_field(p.field, *p.value) : SourceLocation::of_field(p.field);
}

std::string message_of(const std::vector<FieldProblem>& problems) {
  if (problems.empty()) return "a request with problems that were not said";
  std::string out = problems.front().message;
  for (std::size_t i = 1; i < problems.size(); ++i)
    out += "\n" + format_diagnostic(location_of(problems[i]), problems[i].message);
  return out;
}

// "89" as text: a plain number, which is SI.
bool plain_number(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end != nullptr && end != text.c_str() && *end == '\0';
}

}  // namespace

std::string quantity_input_text(const QuantityInput& value) {
  if (const std::string* text = std::get_if<std::string>(&value)) return *text;
  return fmt::format("{}", std::get<double>(value));
}

RequestError::RequestError(std::vector<FieldProblem> problems)
    : InputError(problems.empty() ? SourceLocation{} : location_of(problems.front()),
                 message_of(problems)),
      problems_(std::move(problems)) {}

double FieldChecks::quantity(const QuantityInput& value, Dimension dimension,
                             std::string_view field) {
  if (const double* number = std::get_if<double>(&value)) {
    if (std::isnan(*number)) {
      problem(field, "expected " + dimension_with_article(dimension) + ", found NaN");
      return kUnread;
    }
    return *number;
  }
  const std::string& text = std::get<std::string>(value);
  const std::string name = field_ref(field);
  double parsed = kUnread;
  try {
    parsed = parse_quantity(text, dimension, name);
  } catch (const UnitError& e) {
    std::string message = e.what();
    if (message.starts_with(name + ": ")) message = message.substr(name.size() + 2);
    problem(field, std::move(message));
    return kUnread;
  }
  // A plain number is SI: a length of metres where the rig measures millimetres is said aloud.
  if (plain_number(text) && dimension == Dimension::kLength && std::fabs(parsed) >= 2.0) {
    warnings_.push_back(
        fmt::format("{} read as {} m (a plain number is SI); write {}mm for "
                    "millimetres",
                    field_ref(field, text), text, text));
    warning_fields_.emplace_back(field);
  }
  return parsed;
}

void FieldChecks::plausible(double value, const PlausibleRange& range, std::string_view field,
                            const QuantityInput& input) {
  // Values no bench has in any unit (negative, zero where it cannot be, not finite) are the
  // domain checks' to refuse, with their own words.
  if (has(field) || !std::isfinite(value) || value < 0.0 || (value == 0.0 && range.least > 0.0))
    return;
  const std::optional<std::string> why = implausible(value, range);
  if (!why) return;
  std::string message = *why;
  const std::string* text = std::get_if<std::string>(&input);
  if (text != nullptr && plain_number(*text) && range.per_unit != 1.0) {
    const bool length = range.unit == "mm";
    message += fmt::format(": a plain number is SI, so {} was read as {} {}; write {}{} for {}",
                           *text, *text, length ? "m" : "rad/s", *text, range.unit,
                           length ? "millimetres" : "revolutions a minute");
    for (std::size_t i = warnings_.size(); i-- > 0;)
      if (warning_fields_[i] == field) {
        warnings_.erase(warnings_.begin() + static_cast<std::ptrdiff_t>(i));
        warning_fields_.erase(warning_fields_.begin() + static_cast<std::ptrdiff_t>(i));
      }
  } else if (text != nullptr && plain_number(*text) &&
             !plain_number_advice(value, *text, range).empty()) {
    // A period in milliseconds written as a plain number, which is seconds.
    message += plain_number_advice(value, *text, range);
  } else {
    message += "; check the value and its unit";
  }
  problem(field, quantity_input_text(input), std::move(message));
}

void FieldChecks::plausible(const std::optional<double>& value, const PlausibleRange& range,
                            std::string_view field, const std::optional<QuantityInput>& input) {
  if (value && input) plausible(*value, range, field, *input);
}

std::optional<double> FieldChecks::quantity(const std::optional<QuantityInput>& value,
                                            Dimension dimension, std::string_view field) {
  if (!value) return std::nullopt;
  return quantity(*value, dimension, field);
}

double FieldChecks::positive(const QuantityInput& value, Dimension dimension,
                             std::string_view field, std::string_view what) {
  const double v = quantity(value, dimension, field);
  if (has(field)) return v;
  if (!(v > 0.0) || !std::isfinite(v))
    problem(field, fmt::format("expected {} as a finite positive {}, found {}", what,
                               dimension_name(dimension), quantity_input_text(value)));
  return v;
}

double FieldChecks::not_negative(const QuantityInput& value, Dimension dimension,
                                 std::string_view field, std::string_view what) {
  const double v = quantity(value, dimension, field);
  if (has(field)) return v;
  if (!(v >= 0.0) || !std::isfinite(v))
    problem(field, fmt::format("expected {} as a finite {}, 0 or more, found {}", what,
                               dimension_name(dimension), quantity_input_text(value)));
  return v;
}

void FieldChecks::problem(std::string_view field, std::string message) {
  problems_.push_back({std::string(field), std::move(message), std::nullopt});
}

void FieldChecks::problem(std::string_view field, std::string value, std::string message) {
  problems_.push_back({std::string(field), std::move(message), std::move(value)});
}

void FieldChecks::problem(std::string_view field, const Said& message) {
  problems_.push_back({std::string(field), english(message), std::nullopt, message});
}

bool FieldChecks::has(std::string_view field) const {
  for (const FieldProblem& p : problems_)
    if (p.field == field) return true;
  return false;
}

void FieldChecks::throw_if_any() const {
  if (!problems_.empty()) throw RequestError(problems_);
}

}  // namespace fl
