// Narration that cannot lie (lab/video/caption_values.hpp): a caption's placeholders filled with
// the compiled rig's own values, checked against what the rig computes independently of the
// captions (its mu_k, the thick plate's period from the analytic model, its spacing); a caption
// that names another material or another mu_k is warned about, a formula is not; the video's
// material name tells the plate's look from its friction.
#include "lab/video/caption_values.hpp"

#include <cstdio>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "io/paper_table_yaml.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

PaperTable table() {
  return load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
}

CompiledRig paper_rig(std::vector<SceneOverride> overrides = {}) {
  return compile_rig(test::scene_file("paper-rig.yaml", overrides));
}

TEST(CaptionValues, PlaceholdersTakeTheRunsOwnValues) {
  const CompiledRig rig = paper_rig({{"plate.material", "plexiglas"}});
  const std::vector<Caption> filled = filled_captions(
      {{0.0, std::nullopt, "{material}: mu_k {mu_k}, T {T} at {temperature}, l = {spacing}"}}, rig,
      table());
  // Plexiglas at 300 K: mu_k 0.28 (Table I); its thick-plate period from the analytic model.
  const double period = period_thick(rig.rollers.spacing, 0.28, rig.plate.h_c, rig.world.gravity);
  char expected_period[32];
  std::snprintf(expected_period, sizeof expected_period, "%.3f s", period);
  EXPECT_EQ(filled[0].text,
            std::string("Plexiglas: mu_k 0.28, T ") + expected_period + " at 300 K, l = 89 mm");
}

TEST(CaptionValues, ACaptionThatNamesAnotherMaterialOrMuKIsWarnedAbout) {
  const CompiledRig rig = paper_rig();  // LEGO blocks, mu_k 0.29
  const PaperTable t = table();
  EXPECT_TRUE(caption_contradictions({{0.0, std::nullopt, "LEGO blocks on PVC: mu_k 0.29"},
                                      {1.0, std::nullopt, "μₖ = 2π²l/(gT²), about 0.3"},
                                      {2.0, std::nullopt, "The paper measured T = 0.79 s."}},
                                     rig, t)
                  .empty());
  const std::vector<std::string> said = caption_contradictions(
      {{0.0, std::nullopt, "Iron on PVC"}, {2.5, std::nullopt, "cold PVC: μₖ 0.20, not 0.29"}}, rig,
      t);
  ASSERT_EQ(said.size(), 2u);
  EXPECT_NE(said[0].find("the caption at 0 s names Iron, but this run's plate is LEGO blocks"),
            std::string::npos)
      << said[0];
  EXPECT_NE(said[1].find("the caption at 2.5 s says μₖ 0.20, but this run's mu_k is 0.29"),
            std::string::npos)
      << said[1];
}

TEST(CaptionValues, ThePlatesLookIsToldFromItsFrictionWhenTheyDiffer) {
  const PaperTable t = table();
  EXPECT_EQ(run_material_name(paper_rig(), t), "LEGO blocks");
  EXPECT_EQ(run_material_name(paper_rig({{"plate.material", "plexiglas"}}), t), "Plexiglas");
  EXPECT_EQ(run_material_name(paper_rig({{"friction.mu_k", "plexiglas"}}), t),
            "LEGO blocks plate, Plexiglas's μₖ");
}

}  // namespace
}  // namespace fl
