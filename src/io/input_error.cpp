#include "io/input_error.hpp"

#include <utility>

#include "io/field_ref.hpp"
#include "text/utf8.hpp"

namespace fl {

std::string place_in_file(const SourceLocation& where) {
  std::string out = where.file;
  if (!out.empty() && where.line > 0) {
    out += ':' + std::to_string(where.line);
    if (where.column > 0) out += ':' + std::to_string(where.column);
  }
  return out;
}

std::string format_diagnostic(const SourceLocation& where, std::string_view what) {
  std::string out;
  if (!where.file.empty()) {
    out += place_in_file(where) + ": ";
  } else if (!where.field.empty()) {
    out += where.field_value ? field_ref(where.field, *where.field_value) : field_ref(where.field);
    out += ": ";
  }
  out += "error: ";
  out += what;
  return out;
}

SourceLocation SourceLocation::of_field(std::string path) {
  SourceLocation where;
  where.field = std::move(path);
  return where;
}

SourceLocation SourceLocation::of_field(std::string path, std::string value) {
  SourceLocation where = of_field(std::move(path));
  where.field_value = std::move(value);
  return where;
}

std::string without_location(std::string_view diagnostic) {
  const std::size_t at = diagnostic.find("error: ");
  return std::string(at == std::string_view::npos ? diagnostic : diagnostic.substr(at + 7));
}

// A file name that is not UTF-8 is shown escaped ("bad\xff.csv"): the message goes to JSON and
// to Python, which take UTF-8 only.
InputError::InputError(SourceLocation where, std::string_view what)
    : std::runtime_error(escape_invalid_utf8(format_diagnostic(where, what))),
      where_(std::move(where)) {}

InputError::InputError(SourceLocation where, Said message)
    : InputError(std::move(where), english(message)) {
  said_ = std::move(message);
}

InputError::InputError(SourceLocation where, std::string_view what, std::optional<Said> message)
    : InputError(std::move(where), what) {
  said_ = std::move(message);
}

}  // namespace fl
