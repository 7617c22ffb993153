#include "python/lab_data.hpp"

namespace fl::python {

std::string asset_dir(const std::optional<std::filesystem::path>& given) {
  return fl::asset_dir(given ? given->string() : std::string());
}

}  // namespace fl::python
