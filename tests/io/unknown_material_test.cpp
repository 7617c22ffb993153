// The note for a name that is not a material of Table I: every key of the table, in its order,
// and the closest key when the name looks like a typo of it.
#include "io/unknown_material.hpp"

#include <gtest/gtest.h>

#include "io/paper_table_yaml.hpp"

namespace fl {
namespace {

PaperTable table() {
  return load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
}

constexpr const char* kKnown =
    "the paper's materials are lego, paper, polished-wood, construction-wood, iron, plexiglas, "
    "brass, cardboard, rigid-foam, flexible-foam";

TEST(UnknownMaterial, ListsTheTablesMaterials) {
  EXPECT_EQ(unknown_material_note(table(), "unobtainium"), kKnown);
}

TEST(UnknownMaterial, SuggestsTheClosestKeyForATypo) {
  EXPECT_EQ(unknown_material_note(table(), "plexiglass"),
            std::string(kKnown) + "; did you mean 'plexiglas'?");
  EXPECT_EQ(unknown_material_note(table(), "cardbord"),
            std::string(kKnown) + "; did you mean 'cardboard'?");
}

}  // namespace
}  // namespace fl
