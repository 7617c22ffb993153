#include "serve/temporary_folder.hpp"

#include <stdlib.h>

#include <fstream>
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

std::optional<fs::path> TemporaryFolder::keep(const std::string& name,
                                              std::string_view bytes) const {
  const fs::path file = path_ / name;
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) return std::nullopt;
  return file;
}

std::string without_folder(std::string text, const std::string& folder) {
  for (std::size_t at; (at = text.find(folder)) != std::string::npos;)
    text.erase(at, folder.size());
  return text;
}

nlohmann::json without_folder(nlohmann::json body, const std::string& folder) {
  if (body.is_string()) return without_folder(body.get<std::string>(), folder);
  if (body.is_object() || body.is_array())
    for (auto& value : body) value = without_folder(std::move(value), folder);
  return body;
}

}  // namespace fl::serve
