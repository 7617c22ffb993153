// Errors in what a user gave us (a file, a request's field), located as compilers locate
// theirs: "scenes/x.yaml:12:5: error: plate.thickness: expected a length ..., found "5 xx"", or
// for a field "⟦spacing⟧: error: ..." that each front end spells ("--spacing: error: ..." on the
// command line). Every front end maps it to bad input (exit status 2, Python's InputError).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "text/said.hpp"

namespace fl {

struct SourceLocation {
  SourceLocation() = default;
  SourceLocation(std::string file_name, int line_number = 0, int column_number = 0)
      : file(std::move(file_name)), line(line_number), column(column_number) {}

  std::string file;  // as the user named it; empty for a request's field
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;    // 1-based; 0 when unknown
  // A request's field instead of a file: its path, and the value given when the message quotes
  // it ("set", "friction.mu_k=0.3"); each front end spells it (io/field_ref.hpp).
  std::string field;
  std::optional<std::string> field_value;

  static SourceLocation of_field(std::string path);
  static SourceLocation of_field(std::string path, std::string value);
};

// what() is the located message, its bytes that are not UTF-8 (a file's name) written as \xNN.
// An error made from a Said keeps it, so that a front end can say it in its reader's language.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, std::string_view what);
  InputError(SourceLocation where, Said message);
  InputError(SourceLocation where, std::string_view what, std::optional<Said> message);
  const SourceLocation& where() const { return where_; }
  // The message without its location, as its catalogue id and values; nullopt where it was
  // written in English only.
  const std::optional<Said>& said() const { return said_; }

 private:
  SourceLocation where_;
  std::optional<Said> said_;
};

// "file:line:column" (the parts that are known; "" for a request's field).
std::string place_in_file(const SourceLocation& where);

// "file:line:column: error: what" (parts that are unknown are left out); for a field,
// "⟦field⟧: error: what".
std::string format_diagnostic(const SourceLocation& where, std::string_view what);

// The message of a located diagnostic without its location: the text after "error: ".
std::string without_location(std::string_view diagnostic);

}  // namespace fl
