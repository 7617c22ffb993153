#include "io/text_file.hpp"

#include <cerrno>
#include <cstdint>
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

InputError too_large(const SourceLocation& at, std::string_view what, std::size_t most_bytes) {
  return InputError(at, fmt::format("{} is larger than {} MiB, the most read: expected a file of "
                                    "at most that (split it, or give a shorter one)",
                                    what, most_bytes >> 20));
}

// Lines read so far and the length of the one being read, to refuse one too long at once.
struct LineWatch {
  std::size_t most = 0;   // bytes a line may have (0: any)
  int newline_line = 1;   // 1-based, of the byte being read, counting "\n"
  int return_line = 1;    // the same counting "\r" (for a text whose lines end in "\r" alone)
  bool newlines = false;  // a "\n" was read
  std::size_t length = 0;

  void read(const char* bytes, std::size_t n, const SourceLocation& at, std::string_view what) {
    if (most == 0) return;
    for (std::size_t i = 0; i < n; ++i) {
      const char c = bytes[i];
      if (c == '\n' || c == '\r') {
        newlines = newlines || c == '\n';
        ++(c == '\n' ? newline_line : return_line);
        length = 0;
        continue;
      }
      if (++length <= most) continue;
      throw line_too_long(at.file, newlines ? newline_line : return_line, what, most);
    }
  }
};

std::string read_all(std::istream& in, const SourceLocation& at, std::string_view what,
                     std::size_t most_bytes, std::size_t most_line_bytes,
                     std::size_t expected_bytes = 0) {
  std::string text;
  text.reserve(expected_bytes);  // a file's size: read into one block, not one twice as large
  LineWatch lines{most_line_bytes};
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > most_bytes) throw too_large(at, what, most_bytes);
    lines.read(buffer, got, at, what);
    text.append(buffer, got);
  }
  return text;
}

}  // namespace

InputError line_too_long(const std::string& file, int line, std::string_view what,
                         std::size_t most_line_bytes) {
  return InputError(
      SourceLocation{file, line, 0},
      fmt::format("line {} of {} runs past {} bytes without a line end: expected a text of lines "
                  "(a log's are a few dozen bytes: a time and a value), found a line longer than "
                  "any such text has (a file without line ends, a number of megabytes): is it "
                  "the file meant?",
                  line, what, most_line_bytes));
}

std::string read_text_file(const std::string& path, std::string_view what, std::size_t most_bytes,
                           std::size_t most_line_bytes) {
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
  // A regular file too large is refused by its size, before it is read.
  std::size_t expected = 0;
  if (!ec && fs::is_regular_file(status)) {
    std::error_code size_error;
    const std::uintmax_t size = fs::file_size(path, size_error);
    if (!size_error && size > most_bytes)
      throw too_large(SourceLocation{path, 0, 0}, what, most_bytes);
    if (!size_error) expected = static_cast<std::size_t>(size);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open");
  std::string text =
      read_all(in, SourceLocation{path, 0, 0}, what, most_bytes, most_line_bytes, expected);
  if (in.bad()) throw fail("cannot read");
  return text;
}

std::string read_text_stream(std::istream& in, const std::string& name, std::string_view what,
                             std::size_t most_bytes, std::size_t most_line_bytes) {
  return read_all(in, SourceLocation{name, 0, 0}, what, most_bytes, most_line_bytes);
}

}  // namespace fl
