#include "io/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

// What a path that is not a regular file or a pipe is, for the message.
const char* kind_of(fs::file_type type) {
  switch (type) {
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a file";
  }
}

std::string read_all(std::istream& in, const SourceLocation& at, std::string_view what,
                     std::size_t most_bytes) {
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > most_bytes)
      throw InputError(at, fmt::format("{} is larger than {} MiB, the most read: expected a "
                                       "file of at most that (split it, or give a shorter one)",
                                       what, most_bytes >> 20));
    text.append(buffer, got);
  }
  return text;
}

}  // namespace

std::string read_text_file(const std::string& path, std::string_view what, std::size_t most_bytes) {
  const auto fail = [&](std::string_view why) {
    return InputError(SourceLocation{path, 0, 0},
                      std::string(why) + " " + std::string(what) + ": " + std::strerror(errno));
  };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!ec && fs::is_directory(status)) {
    errno = EISDIR;
    throw fail("cannot read");
  }
  if (!ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_fifo(status))
    throw InputError(SourceLocation{path, 0, 0},
                     fmt::format("expected {} as a file, found {}, which is never read: give a "
                                 "file (or '-' for standard input where one is taken)",
                                 what, kind_of(status.type())));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open");
  std::string text = read_all(in, SourceLocation{path, 0, 0}, what, most_bytes);
  if (in.bad()) throw fail("cannot read");
  return text;
}

std::string read_text_stream(std::istream& in, const std::string& name, std::string_view what,
                             std::size_t most_bytes) {
  return read_all(in, SourceLocation{name, 0, 0}, what, most_bytes);
}

}  // namespace fl
