// compare --log: a log against its simulation. The logs are simulated here with a known truth: a
// mu_k other than the scene's (the refit must find it), rollers that warm (a drift the scene
// without warming lacks), and off-centre tubes that make the plate jump (a scatter the true
// rollers lack); each must be found, and a log of the scene itself must agree in every test.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/hall_log.hpp"
#include "lab/experiment.hpp"
#include "lab/log_against_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

const std::string kScenes = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/";
const PaperTableSource kPaper = []() -> const PaperTable& { return test::paper_table(); };
const PartCatalogSource kParts = []() -> const assets::PartCatalog& {
  return test::part_catalog();
};

// The Hall signal of a scene run, as a log.
HallLog simulated_log(const std::string& scene_file, const std::vector<SceneOverride>& overrides) {
  const Scene scene = load_scene_file(kScenes + scene_file, overrides, kPaper, kParts);
  RunOptions run;
  run.record_hall = true;
  RunRecording recording;
  run_experiment(scene, run, &recording);
  std::vector<double> t, adc;
  for (const HallSample& s : recording.hall) {
    t.push_back(s.t_us * 1e-6);
    adc.push_back(s.adc);
  }
  return hall_log_from_samples(std::move(t), adc, scene_file);
}

LogAgainstRig against(const HallLog& log, const std::string& scene_file,
                      fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry) {
  CompareOptions options;
  options.scene_file = kScenes + scene_file;
  options.paper = kPaper;
  options.parts = kParts;
  return compare_log_with_rig(log, geometry, options);
}

bool found(const LogAgainstRig& r, const std::string& what) {
  for (const std::string& d : r.disagreements)
    if (d.starts_with(what)) return true;
  return false;
}

TEST(LogAgainstRig, TheRefitFindsTheLogsMuKAndTheSignalsAgree) {
  // A log of the paper's rig at mu_k 0.25, against the scene at its own 0.29.
  const HallLog log = simulated_log("paper-rig.yaml", {{"friction.mu_k", "0.25"}});
  const LogAgainstRig r = against(log, "paper-rig.yaml");
  const CompareRow& row = r.fit.rows.front();
  EXPECT_DOUBLE_EQ(row.mu_k_simulated, 0.29);
  ASSERT_TRUE(row.mu_k_refit) << row.refit_note;
  // The refit matches the log's estimated T within 1e-4 (its tolerance); the log's T is within
  // its standard error (about 5e-5 T here) of the truth, so mu_k (T ~ mu^-1/2) within 4e-4.
  EXPECT_NEAR(*row.mu_k_refit / 0.25, 1.0, 4e-4);
  EXPECT_TRUE(r.disagreements.empty()) << r.disagreements.front();
  // Aligned on the first pulse, the same rig at the same mu_k: the residual is the sensor's noise
  // (2 mV, 0.4 counts) and rounding, far below the pulses' 180 counts.
  EXPECT_LT(r.residual_rms, 0.02 * r.measured.pulse_height);
}

TEST(LogAgainstRig, WarmingRollersShowAsADrift) {
  const HallLog log = simulated_log("imperfect/rollers-warming.yaml", {});
  const LogAgainstRig r = against(log, "paper-rig-77K.yaml");
  EXPECT_TRUE(found(r, "drift:")) << (r.disagreements.empty() ? "" : r.disagreements.front());
  // Warming rollers lower mu_k toward 0.29: the period falls.
  ASSERT_TRUE(r.measured.period_drift);
  EXPECT_LT(*r.measured.period_drift, 0.0);
  EXPECT_FALSE(found(r, "jumps:"));
}

TEST(LogAgainstRig, AJumpingPlateShowsAsScatter) {
  const HallLog log = simulated_log("imperfect/runout.yaml", {});
  // The jumps bend the pulses: the geometry is said, as a student would after estimate asks.
  const LogAgainstRig r = against(log, "paper-rig.yaml", fl_estimator::kOnePulse);
  EXPECT_TRUE(found(r, "periods:")) << (r.disagreements.empty() ? "" : r.disagreements.front());
  EXPECT_FALSE(found(r, "drift:"));
}

}  // namespace
}  // namespace fl
