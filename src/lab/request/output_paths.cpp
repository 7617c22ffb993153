#include "lab/request/output_paths.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "io/input_error.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& field, const std::string& path,
                         const std::string& found) {
  throw InputError(
      SourceLocation::of_field(field, path),
      "expected a place this command can write, found " + found + "; give another path");
}

// Whether a file can be made in `folder`: a probe made and removed at once. (access() is not
// enough: root passes it for /proc and read-only mounts, where nothing can be written.)
std::string cannot_write_into(const fs::path& folder) {
  static std::atomic<int> count{0};
  const fs::path probe =
      folder / (".frictionlab-probe-" + std::to_string(::getpid()) + "-" + std::to_string(++count));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return std::strerror(errno);
  ::close(fd);
  ::unlink(probe.c_str());
  return "";
}

// Whether `a` and `b` are the one file: the same file on disk (links, other spellings), or the
// same path once made canonical (a file not written yet).
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  std::error_code ec_a;
  std::error_code ec_b;
  const fs::path canonical_a = fs::weakly_canonical(a, ec_a);
  const fs::path canonical_b = fs::weakly_canonical(b, ec_b);
  return !ec_a && !ec_b && canonical_a == canonical_b;
}

// The input `output` would overwrite, if any.
const InputFile* overwritten(const fs::path& output, const std::vector<InputFile>& inputs) {
  for (const InputFile& in : inputs)
    if (!in.path.empty() && in.path != "-" && same_file(output, in.path)) return &in;
  return nullptr;
}

}  // namespace

void refuse_overwriting_inputs(const std::string& output, const std::string& field,
                               const std::vector<InputFile>& inputs) {
  if (output.empty()) return;
  if (const InputFile* in = overwritten(output, inputs))
    throw InputError(SourceLocation::of_field(field, output),
                     "expected a file to write, found " + output + ", which is " + in->what +
                         " this command reads (" + in->path +
                         "): writing it would replace it; name another file");
}

void refuse_overwriting_inputs(const std::string& folder, const std::vector<std::string>& names,
                               const std::string& field, const std::vector<InputFile>& inputs) {
  if (folder.empty()) return;
  for (const std::string& name : names) {
    const fs::path output = fs::path(folder) / name;
    if (const InputFile* in = overwritten(output, inputs))
      throw InputError(SourceLocation::of_field(field, folder),
                       "expected a folder whose files leave this command's inputs alone, found " +
                           folder + ", where " + name + " would replace " + in->what + " (" +
                           in->path + "); give another folder");
  }
}

void prepare_output_folder(const std::string& folder, const std::string& field) {
  std::error_code ec;
  const fs::path path(folder);
  if (fs::exists(path, ec) && !fs::is_directory(path, ec)) refuse(field, folder, "a file");
  fs::create_directories(path, ec);
  if (ec) refuse(field, folder, "a folder that cannot be created (" + ec.message() + ")");
  if (const std::string why = cannot_write_into(path); !why.empty())
    refuse(field, folder, "a folder nothing can be written into (" + why + ")");
}

void prepare_output_file(const std::string& file, const std::string& field) {
  std::error_code ec;
  const fs::path path(file);
  if (fs::is_directory(path, ec))
    refuse(field, file, "a folder (name a file in it, e.g. " + (path / "run.mp4").string() + ")");
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (fs::exists(parent, ec) && !fs::is_directory(parent, ec))
    refuse(field, file, "a path whose folder " + parent.string() + " is a file");
  fs::create_directories(parent, ec);
  if (ec) refuse(field, file, "a folder that cannot be created (" + ec.message() + ")");
  if (const std::string why = cannot_write_into(parent); !why.empty())
    refuse(field, file, "a folder nothing can be written into (" + why + ")");
  if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0)
    refuse(field, file, "a file this user cannot overwrite");
}

}  // namespace fl
