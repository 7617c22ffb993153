// libFuzzer target for the scene loader: any input either loads or is refused with an
// InputError; anything else (a crash, a sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"
#include "scene/scene_yaml.hpp"

namespace {

const fl::PaperTable& table() {
  static const fl::PaperTable t = fl::load_paper_table(fl::paper_table_path(FRICTIONLAB_ASSET_DIR));
  return t;
}

const fl::assets::PartCatalog& parts() {
  static const fl::assets::PartCatalog c =
      fl::assets::load_part_catalog(fl::assets::part_catalog_path(FRICTIONLAB_ASSET_DIR));
  return c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const fl::Scene scene = fl::load_scene_text(
        text, "fuzz.yaml", {}, []() -> const fl::PaperTable& { return table(); },
        []() -> const fl::assets::PartCatalog& { return parts(); });
    (void)scene;
  } catch (const fl::InputError&) {
    // A refused input: expected.
  }
  return 0;
}
