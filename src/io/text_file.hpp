// Reading a whole file into memory (scenes, sweep files, plans, point files, Hall logs).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>

#include "io/input_error.hpp"

namespace fl {

// The most bytes a file is read to (a Hall log of a day at 1 kHz is about 1.5 GB; an hour's, the
// longest a rig is run, about 60 MB).
inline constexpr std::size_t kMostTextFileBytes = std::size_t{512} << 20;

// The file's bytes. Throws InputError located at `path` when it cannot be read:
// "PATH: error: cannot open WHAT: No such file or directory" (`what` names it for the reader:
// "the log", "the scene"; by default "the file"). Only a regular file or a pipe is read (a
// device such as /dev/urandom or a terminal never ends, and is refused, saying so), and at most
// `most_bytes` of it: a larger one is refused, saying how large it may be (a regular file by its
// size, before a byte of it is read). With `most_line_bytes` (0: none), a line (up to "\n" or
// "\r") longer than that is refused as soon as it is read, located at its line: a text of lines
// has none so long (a file without line ends, one number of megabytes).
std::string read_text_file(const std::string& path, std::string_view what = "the file",
                           std::size_t most_bytes = kMostTextFileBytes,
                           std::size_t most_line_bytes = 0);

// The error for a line longer than `most_line_bytes` (as read_text_file throws it), for a text
// split into lines elsewhere.
InputError line_too_long(const std::string& file, int line, std::string_view what,
                         std::size_t most_line_bytes);

// Reads a stream (standard input) the same way, to at most `most_bytes`; `name` locates it.
std::string read_text_stream(std::istream& in, const std::string& name, std::string_view what,
                             std::size_t most_bytes = kMostTextFileBytes,
                             std::size_t most_line_bytes = 0);

}  // namespace fl
