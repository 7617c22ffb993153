#include "lab/request/output_paths.hpp"

#include <unistd.h>

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

}  // namespace

void prepare_output_folder(const std::string& folder, const std::string& field) {
  std::error_code ec;
  const fs::path path(folder);
  if (fs::exists(path, ec) && !fs::is_directory(path, ec)) refuse(field, folder, "a file");
  fs::create_directories(path, ec);
  if (ec) refuse(field, folder, "a folder that cannot be created (" + ec.message() + ")");
  if (::access(path.c_str(), W_OK | X_OK) != 0)
    refuse(field, folder, "a folder this user cannot write into");
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
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    refuse(field, file, "a folder this user cannot write into");
  if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0)
    refuse(field, file, "a file this user cannot overwrite");
}

}  // namespace fl
