// Scene files (scenes/*.yaml, format 1; docs/scene-format.md) read into a Scene, strictly:
// unknown keys are errors with a suggestion, every value needs its unit (plain numbers mean SI),
// and physically impossible set-ups are refused with the reason, located at the key responsible.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "assets/part_catalog.hpp"
#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "scene/scene.hpp"

namespace fl {

// One override of a scene key, as a request's `set` field holds it: "plate.thickness=5 mm".
struct SceneOverride {
  std::string path;   // "plate.thickness"
  std::string value;  // "5 mm" (read as YAML)
};

// Splits "key.path=value"; throws InputError if there is no '=' or no key.
SceneOverride parse_override(std::string_view text);

// Where an override stands in messages: the request's field "set" with "key.path=value".
SourceLocation override_location(const SceneOverride& o);

// Whether an error is located at the override of `path` (a sweep's or a row's own key).
bool located_at_override(const InputError& e, std::string_view path);

// The paper's table, loaded only if a scene names one of its materials.
using PaperTableSource = std::function<const PaperTable&()>;

// The LEGO part index (assets/lego/parts.yaml), read only if a scene names LEGO parts (a frame,
// blocks on the plate, a gearbox). Without one, such a scene is refused with a clear message.
using PartCatalogSource = std::function<const assets::PartCatalog&()>;

// What loading a scene may ask for: the paper's Table I (a material named for mu_k) and the LEGO
// part index (a scene with a frame, blocks or a gearbox). Either may be empty if no scene needs it.
struct SceneInputs {
  PaperTableSource paper;
  PartCatalogSource parts;
};

Scene load_scene_file(const std::string& file, std::span<const SceneOverride> overrides,
                      const PaperTableSource& paper, const PartCatalogSource& parts = {});

// The same from text (tests, inline scenes); `name` stands for the file in messages.
Scene load_scene_text(std::string_view text, const std::string& name,
                      std::span<const SceneOverride> overrides, const PaperTableSource& paper,
                      const PartCatalogSource& parts = {});

}  // namespace fl
