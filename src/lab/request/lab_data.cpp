#include "lab/request/lab_data.hpp"

#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "assets/part_catalog.hpp"
#include "io/paper_table_yaml.hpp"

namespace fl {
namespace {

// One folder's files, each read once.
struct LabData {
  std::mutex mutex;
  std::optional<PaperTable> paper;
  std::optional<assets::PartCatalog> parts;
};

std::shared_ptr<LabData> lab_data(const std::string& dir) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<LabData>> folders;
  const std::lock_guard lock(mutex);
  std::shared_ptr<LabData>& data = folders[dir];
  if (!data) data = std::make_shared<LabData>();
  return data;
}

}  // namespace

std::string asset_dir(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("FRICTIONLAB_ASSETS"); env != nullptr && *env != '\0')
    return env;
  return FRICTIONLAB_DEFAULT_ASSET_DIR;
}

SceneInputs scene_inputs(const std::string& dir) {
  const std::shared_ptr<LabData> data = lab_data(dir);
  SceneInputs inputs;
  inputs.paper = [data, dir]() -> const PaperTable& {
    const std::lock_guard lock(data->mutex);
    if (!data->paper) data->paper = load_paper_table(paper_table_path(dir));
    return *data->paper;
  };
  inputs.parts = [data, dir]() -> const assets::PartCatalog& {
    const std::lock_guard lock(data->mutex);
    if (!data->parts) data->parts = assets::load_part_catalog(assets::part_catalog_path(dir));
    return *data->parts;
  };
  return inputs;
}

const PaperTable& paper_table_in(const std::string& dir) {
  return scene_inputs(dir).paper();
}

}  // namespace fl
