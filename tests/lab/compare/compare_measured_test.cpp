// compare --measured: rows of your own (here periods from the thick-plate closed form at three
// roller spacings, an independent truth the simulation should reproduce within its 0.05 %), each
// simulated in its own rig, and mu_k refitted; a row whose keys make no rig is refused at its cell
// before any simulation.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/analytic_model.hpp"
#include "lab/compare/compare.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

const std::string kMinimal = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
const PaperTableSource kPaper = []() -> const PaperTable& { return test::paper_table(); };

CompareOptions minimal_options() {
  CompareOptions o;
  o.scene_file = kMinimal;
  o.paper = kPaper;
  o.workers = 2;
  return o;
}

TEST(CompareMeasured, RowsAtTheirOwnSpacingsRefitTheClosedFormsMuK) {
  // The minimal rig's h_c (its plate does not change with the spacing).
  const Scene scene = load_scene_file(kMinimal, {}, kPaper, {});
  const double h_c = compile_rig(scene).plate.h_c;
  const double g = compile_rig(scene).world.gravity;
  const double mu = 0.33;
  std::string csv = "label,rollers.spacing,period,period_err,spacing_err\n";
  const double spacings[] = {0.070, 0.089, 0.110};
  for (double l : spacings)
    csv += fmt::format("l{},{} m,{} s,0.005 s,1 mm\n", l * 1e3, l, period_thick(l, mu, h_c, g));
  const MeasuredRows rows = parse_measured_rows(csv, "series.csv");
  const CompareResult r = run_compare(rows, minimal_options());
  ASSERT_EQ(r.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const CompareRow& row = r.rows[i];
    SCOPED_TRACE(row.label + ": " + row.reason + " " + row.refit_note);
    ASSERT_EQ(row.status, "compared");
    EXPECT_DOUBLE_EQ(row.spacing, spacings[i]);
    EXPECT_FALSE(row.mu_k_reported);
    // The first run used the scene's own mu_k (no mu_k column): its period is the thick curve's
    // at that mu_k and the row's l, within the spacing sweep's 0.05 %.
    ASSERT_TRUE(row.period_simulated);
    EXPECT_NEAR(*row.period_simulated / period_thick(spacings[i], scene.friction.mu_k, h_c, g), 1.0,
                5e-4);
    ASSERT_TRUE(row.mu_k_refit);
    // The simulation reproduces the thick curve within 0.05 % in T (the spacing sweep's claim),
    // so mu_k (T ~ mu^-1/2) within about 0.1 %.
    EXPECT_NEAR(*row.mu_k_refit / mu, 1.0, 1e-3);
    // dl = 1 mm and dT = 5 ms carried through the simulation's sensitivities: near the closed
    // form's quadrature rule (its kappa's are within a few % of the simulation's).
    const MuKUncertainty closed = mu_k_with_uncertainty(period_thick(spacings[i], mu, h_c, g),
                                                        0.005, spacings[i], 0.001, h_c, g);
    EXPECT_NEAR(*row.mu_k_refit_err_quadrature / closed.quadrature, 1.0, 0.05);
  }
}

TEST(CompareMeasured, ARowWhoseKeysMakeNoRigIsRefusedAtItsCellBeforeAnyRun) {
  const MeasuredRows rows = parse_measured_rows(
      "label,plate.material,period,period_err\nok,lego,0.79 s,0.03 s\nbad,unobtainium,0.8 s,0.03 "
      "s\n",
      "mine.csv");
  try {
    run_compare(rows, minimal_options());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mine.csv:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("row \"bad\""), std::string::npos) << what;
    EXPECT_NE(what.find("unobtainium"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace fl
