#include "io/appending_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/input_error.hpp"

namespace fl {

AppendingFile::AppendingFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(SourceLocation{path_, 0, 0},
                     "cannot write " + what_ + ": " + std::strerror(errno));
}

AppendingFile::~AppendingFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendingFile::write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw InputError(SourceLocation{path_, 0, 0},
                       "cannot write " + what_ + ": " + std::strerror(errno));
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void AppendingFile::sync() {
  ::fsync(fd_);
}

}  // namespace fl
