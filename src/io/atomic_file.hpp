// Writes a file so that readers see either the old content or the whole new one, never a part:
// the content goes to a temporary file in the same folder, is flushed to disk, then renamed (a
// StreamedFile written at once, io/streamed_file.hpp).
#pragma once

#include <string>
#include <string_view>

namespace fl {

// Throws std::runtime_error naming the path if it cannot write.
void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace fl
