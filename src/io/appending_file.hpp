// A file written as its bytes arrive (a serial port's lines): each piece with write(2) and no
// buffer, so the file holds everything written up to any moment, however the program ends.
// `estimate --follow --log` and the server's rig record write through it.
#pragma once

#include <string>
#include <string_view>

namespace fl {

class AppendingFile {
 public:
  // Creates (or empties) the file. Throws InputError located at `path`, saying why it cannot;
  // `what` names the file in messages ("the raw log").
  AppendingFile(std::string path, std::string what);
  ~AppendingFile();
  AppendingFile(const AppendingFile&) = delete;
  AppendingFile& operator=(const AppendingFile&) = delete;

  // Throws InputError located at the path when the bytes cannot all be written.
  void write(std::string_view bytes);
  // Asks the system to put what was written on the disk (fsync).
  void sync();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string what_;
  int fd_ = -1;
};

}  // namespace fl
