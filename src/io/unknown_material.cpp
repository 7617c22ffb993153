#include "io/unknown_material.hpp"

#include <vector>

#include "io/suggest.hpp"

namespace fl {

std::string unknown_material_note(const PaperTable& table, std::string_view name) {
  std::string note = "the paper's materials are ";
  std::vector<std::string_view> keys;
  for (const PaperMaterial& m : table.materials) {
    note += (keys.empty() ? "" : ", ") + m.key;
    keys.push_back(m.key);
  }
  const std::string suggestion = closest_match(name, keys);
  if (!suggestion.empty()) note += "; did you mean '" + suggestion + "'?";
  return note;
}

std::string unknown_material_message(const PaperTable& table, std::string_view name) {
  return "unknown material \"" + std::string(name) + "\"; " + unknown_material_note(table, name);
}

}  // namespace fl
