#include "io/streamed_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fl {
namespace {

// Written out in pieces of this size: large enough for few system calls, small against a run.
constexpr std::size_t kPieceBytes = 1 << 18;

}  // namespace

StreamedFile::StreamedFile(std::string path) : path_(std::move(path)) {
  const std::filesystem::path target(path_);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  temp_ = path_ + ".tmp.XXXXXX";
  fd_ = mkstemp(temp_.data());
  if (fd_ < 0)
    throw std::runtime_error("cannot create a temporary file beside " + path_ + ": " +
                             std::strerror(errno));
  pending_.reserve(kPieceBytes + 4096);
}

StreamedFile::~StreamedFile() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(temp_.c_str());
  }
}

void StreamedFile::wrote() {
  if (pending_.size() >= kPieceBytes) write_pending();
}

void StreamedFile::write_pending() {
  std::size_t written = 0;
  while (written < pending_.size()) {
    const ssize_t n = ::write(fd_, pending_.data() + written, pending_.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
    }
    written += static_cast<std::size_t>(n);
  }
  pending_.clear();
}

void StreamedFile::restart() {
  pending_.clear();
  if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0)
    throw std::runtime_error("cannot start " + path_ + " again: " + std::strerror(errno));
}

void StreamedFile::commit() {
  write_pending();
  // Readable like any file we write (mkstemp makes it 0600).
  ::fchmod(fd_, 0644);
  const int fd = fd_;
  fd_ = -1;
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(temp_.c_str());
    throw std::runtime_error("cannot flush " + path_ + " to disk");
  }
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temp_.c_str());
    throw std::runtime_error("cannot move the finished file into place at " + path_ + ": " + why);
  }
}

}  // namespace fl
