#include "io/input_error.hpp"

#include <utility>

namespace fl {

std::string format_diagnostic(const SourceLocation& where, std::string_view what) {
  std::string out;
  if (!where.file.empty()) {
    out += where.file;
    if (where.line > 0) {
      out += ':' + std::to_string(where.line);
      if (where.column > 0) out += ':' + std::to_string(where.column);
    }
    out += ": ";
  }
  out += "error: ";
  out += what;
  return out;
}

InputError::InputError(SourceLocation where, std::string_view what)
    : std::runtime_error(format_diagnostic(where, what)), where_(std::move(where)) {}

}  // namespace fl
