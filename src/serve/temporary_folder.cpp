#include "serve/temporary_folder.hpp"

#include <stdlib.h>

#include <stdexcept>
#include <system_error>

namespace fl::serve {

namespace fs = std::filesystem;

TemporaryFolder::TemporaryFolder() {
  std::string pattern = (fs::temp_directory_path() / "frictionlab-upload-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("the server could not make a temporary folder for the file");
  path_ = pattern;
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

nlohmann::json without_folder(nlohmann::json body, const std::string& folder) {
  if (body.is_string()) {
    std::string text = body.get<std::string>();
    for (std::size_t at; (at = text.find(folder)) != std::string::npos;)
      text.erase(at, folder.size());
    return text;
  }
  if (body.is_object() || body.is_array())
    for (auto& value : body) value = without_folder(std::move(value), folder);
  return body;
}

}  // namespace fl::serve
