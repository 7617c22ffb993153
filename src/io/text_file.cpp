#include "io/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/input_error.hpp"

namespace fl {

std::string read_text_file(const std::string& path, std::string_view what) {
  const auto fail = [&](std::string_view why) {
    return InputError(SourceLocation{path, 0, 0},
                      std::string(why) + " " + std::string(what) + ": " + std::strerror(errno));
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    errno = EISDIR;
    throw fail("cannot read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open");
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw fail("cannot read");
  return text;
}

}  // namespace fl
