#include "text/decimal.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace fl {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// Whether [at, last) starts with `word`, in any case.
bool starts_with_word(const char* at, const char* last, const char* word) {
  for (; *word != '\0'; ++word, ++at)
    if (at == last || lower(*at) != *word) return false;
  return true;
}

// Where the number that starts at `first` ends (after an optional '-'), by from_chars' grammar
// for std::chars_format::general; `first` when none starts there.
const char* number_end(const char* first, const char* last) {
  const char* at = first;
  if (at != last && *at == '-') ++at;
  if (starts_with_word(at, last, "infinity")) return at + 8;
  if (starts_with_word(at, last, "inf")) return at + 3;
  if (starts_with_word(at, last, "nan")) {
    at += 3;
    // nan(n-char-sequence) with letters, digits and '_' only.
    if (at != last && *at == '(') {
      const char* close = at + 1;
      while (close != last &&
             (is_digit(*close) || (lower(*close) >= 'a' && lower(*close) <= 'z') || *close == '_'))
        ++close;
      if (close != last && *close == ')') return close + 1;
    }
    return at;
  }
  const char* digits = at;
  while (at != last && is_digit(*at)) ++at;
  bool any = at != digits;
  if (at != last && *at == '.') {
    const char* fraction = ++at;
    while (at != last && is_digit(*at)) ++at;
    any = any || at != fraction;
  }
  if (!any) return first;
  if (at != last && (*at == 'e' || *at == 'E')) {
    const char* exponent = at + 1;
    if (exponent != last && (*exponent == '+' || *exponent == '-')) ++exponent;
    if (exponent != last && is_digit(*exponent)) {
      at = exponent;
      while (at != last && is_digit(*at)) ++at;
    }
  }
  return at;
}

}  // namespace

std::from_chars_result read_decimal(const char* first, const char* last, double& value) {
#if defined(__GLIBCXX__) || (defined(_LIBCPP_VERSION) && _LIBCPP_VERSION >= 170000)
  return std::from_chars(first, last, value);
#else
  return read_decimal_by_strtod(first, last, value);
#endif
}

std::from_chars_result read_decimal_by_strtod(const char* first, const char* last, double& value) {
  const char* end = number_end(first, last);
  if (end == first) return {first, std::errc::invalid_argument};
  // strtod reads the same grammar (and more, which number_end has cut off); the C locale's
  // decimal point, which Emscripten's libc keeps.
  const std::string text(first, end);
  errno = 0;
  const double read = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && (std::isinf(read) || read == 0.0))
    return {end, std::errc::result_out_of_range};
  value = read;
  return {end, std::errc{}};
}

}  // namespace fl
