// A file a page sent, kept only while the lab reads it: a private folder (mode 0700) that goes
// with the object, and the answer's texts without the folder's place (the file reads as its own
// name, and the server's folders stay its own).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace fl::serve {

class TemporaryFolder {
 public:
  TemporaryFolder();  // throws std::runtime_error where none can be made
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // "/tmp/frictionlab-upload-XXXXXX/": what without_folder takes out.
  std::string prefix() const { return path_.string() + "/"; }
  // Writes `bytes` as the file `name` in the folder: its path, or nullopt where it could not be
  // kept (a disk full).
  std::optional<std::filesystem::path> keep(const std::string& name, std::string_view bytes) const;

 private:
  std::filesystem::path path_;
};

// Every mention of `folder` (a TemporaryFolder's prefix) in the text, or in the body's texts,
// taken out.
std::string without_folder(std::string text, const std::string& folder);
nlohmann::json without_folder(nlohmann::json body, const std::string& folder);

}  // namespace fl::serve
