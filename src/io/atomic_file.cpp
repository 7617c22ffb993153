#include "io/atomic_file.hpp"

#include "io/streamed_file.hpp"

namespace fl {

void write_file_atomic(const std::string& path, std::string_view content) {
  StreamedFile file(path);
  file.pending().assign(content);
  file.commit();
}

}  // namespace fl
