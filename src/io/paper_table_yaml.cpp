#include "io/paper_table_yaml.hpp"

#include "io/yaml_node.hpp"

namespace fl {
namespace {

PaperMeasurement read_measurement(const YamlNode& node, double temperature) {
  node.allow_keys({"period", "mu_k", "literature"});
  PaperMeasurement m;
  m.temperature = temperature;
  m.period = node.at("period").measured(Dimension::kTime);
  m.mu_k = node.at("mu_k").measured(Dimension::kDimensionless);
  if (m.period.value <= 0.0) node.at("period").fail("a period must be positive");
  if (m.mu_k.value <= 0.0) node.at("mu_k").fail("mu_k must be positive");
  return m;
}

}  // namespace

std::string paper_table_path(const std::string& asset_dir) {
  return asset_dir + "/paper/table1.yaml";
}

PaperTable load_paper_table(const std::string& file) {
  const YamlNode root = load_yaml_file(file);
  root.allow_keys({"format", "source", "spacing", "rollers", "materials"});
  if (root.at("format").integer() != 1) root.at("format").fail("this build reads format 1");
  PaperTable table;
  table.source = root.at("source").text();
  table.spacing = root.at("spacing").measured(Dimension::kLength);
  const YamlNode materials = root.at("materials");
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const YamlNode entry = materials[i];
    entry.allow_keys({"key", "name", "note", "300K", "77K"});
    PaperMaterial material;
    material.key = entry.at("key").text();
    material.name = entry.at("name").text();
    if (auto note = entry.find("note")) material.note = note->text();
    const YamlNode room = entry.at("300K");
    material.room = read_measurement(room, 300.0);
    if (auto range = room.find("literature")) {
      if (range->size() != 2) range->fail("expected [low, high]");
      material.literature = LiteratureRange{(*range)[0].number(), (*range)[1].number()};
      if (material.literature->low > material.literature->high)
        range->fail("expected [low, high] with low <= high");
    }
    if (auto cold = entry.find("77K")) {
      if (cold->has("literature")) cold->at("literature").fail("only the 300 K rows have one");
      material.cold = read_measurement(*cold, 77.0);
    }
    if (table.find(material.key) != nullptr)
      entry.at("key").fail("the material '" + material.key + "' is listed twice");
    table.materials.push_back(std::move(material));
  }
  return table;
}

}  // namespace fl
