// Errors in what a user gave us (a file, a command-line value), located as compilers locate
// theirs: "scenes/x.yaml:12:5: error: plate.thickness: expected a length ..., found "5 xx"".
// The command line maps it to exit status 2.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace fl {

struct SourceLocation {
  std::string file;  // as the user named it; empty for the command line
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;    // 1-based; 0 when unknown
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, std::string_view what);
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

// "file:line:column: error: what" (parts that are unknown are left out).
std::string format_diagnostic(const SourceLocation& where, std::string_view what);

}  // namespace fl
