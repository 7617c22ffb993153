// Reading a whole file into memory (scenes, sweep files, plans, point files, Hall logs).
#pragma once

#include <string>
#include <string_view>

namespace fl {

// The file's bytes. Throws InputError located at `path` when it cannot be read:
// "PATH: error: cannot open WHAT: No such file or directory" (`what` names it for the reader:
// "the log", "the scene"; by default "the file").
std::string read_text_file(const std::string& path, std::string_view what = "the file");

}  // namespace fl
