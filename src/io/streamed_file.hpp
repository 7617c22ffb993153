// A file written in pieces while a job runs, which readers still see only whole: the pieces go,
// buffered, to a temporary file beside it; commit() flushes it to disk and renames it into place
// (as io/atomic_file.hpp does for a file written at once). A file never committed (the job
// failed, or threw) is removed, and the old file at the path, if any, is left as it was.
#pragma once

#include <string>
#include <string_view>

namespace fl {

class StreamedFile {
 public:
  // Creates the temporary file. Throws std::runtime_error naming the path if it cannot.
  explicit StreamedFile(std::string path);
  ~StreamedFile();
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;

  // The text not yet written: append to it, then call wrote() (which writes it out once it is
  // large, so memory stays bounded whatever the file's length).
  std::string& pending() { return pending_; }
  void wrote();
  // Forgets everything written so far (the job starts again).
  void restart();
  // Writes the rest, flushes to disk and moves the file into place. Throws std::runtime_error
  // naming the path if it cannot; the temporary file is then removed.
  void commit();

  const std::string& path() const { return path_; }

 private:
  void write_pending();
  std::string path_;
  std::string temp_;
  int fd_ = -1;
  std::string pending_;
};

}  // namespace fl
