#include "text/text.hpp"

#include <sstream>

namespace fl {

std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::string_view trim(std::string_view s, std::string_view strip) {
  const std::size_t first = s.find_first_not_of(strip);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(strip) - first + 1);
}

std::string shown_number(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

}  // namespace fl
