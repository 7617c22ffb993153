// The one table of result fields: names that do not collide; and the rule that a period (and
// the mu_k from it) exists only for a harmonic oscillation, with null (never 0) where the run
// measured nothing.
#include "lab/run/summary_fields.hpp"

#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

Scene minimal_scene(std::vector<SceneOverride> overrides = {}) {
  return test::scene_file("minimal.yaml", overrides);
}

TEST(SummaryFields, NamesAreUniqueAndEveryFieldIsWrittenSomewhere) {
  std::set<std::string> keys, columns, attributes;
  for (const SummaryField& f : summary_fields()) {
    EXPECT_TRUE(f.json != nullptr || f.sweep != nullptr || f.python != nullptr);
    EXPECT_NE(std::string(f.meaning), "");
    EXPECT_NE(f.get, nullptr);
    if (f.json != nullptr) {
      EXPECT_TRUE(keys.insert(f.json).second) << f.json;
    }
    if (f.sweep != nullptr) {
      EXPECT_TRUE(columns.insert(f.sweep).second) << f.sweep;
    }
    if (f.python != nullptr) {
      EXPECT_TRUE(attributes.insert(f.python).second) << f.python;
    }
    // A key left out when null says when.
    if (f.omit_when_null) {
      EXPECT_NE(f.null_when, nullptr) << f.json;
    }
  }
}

// A field that says it is never null is never null, and its unit is what its key's suffix says
// (`_s` seconds, `_m` metres, ...): over runs that reach every regime's fields.
TEST(SummaryFields, NullRulesAndUnitsHoldOverRunsOfEveryKind) {
  std::vector<RunSummary> runs;
  runs.push_back(run_experiment(minimal_scene({{"world.duration", "3 s"}}), {}));
  runs.push_back(run_experiment(minimal_scene({{"world.duration", "3 s"},
                                               {"rollers.speed", "200 rpm"},
                                               {"plate.offset", "30 mm"},
                                               {"friction.mu_s", "0.348"}}),
                                {}));
  Scene bare = minimal_scene({{"world.duration", "3 s"}});
  bare.sensor.reset();
  runs.push_back(run_experiment(bare, {}));
  const std::vector<std::pair<std::string, std::string>> suffixes = {
      {"_m_s2", "m/s^2"}, {"_rad_s", "rad/s"}, {"_m_s", "m/s"}, {"_per_s", "1/s"},
      {"_rad", "rad"},    {"_kg", "kg"},       {"_n", "N"},     {"temperature_k", "K"},
      {"_m", "m"},        {"_s", "s"}};
  for (const SummaryField& f : summary_fields()) {
    for (const RunSummary& r : runs) {
      if (f.null_when == nullptr) {
        EXPECT_FALSE(f.get(r).is_none()) << (f.json ? f.json : f.python);
      }
    }
    const std::string name = f.json ? f.json : (f.sweep ? f.sweep : "");
    std::string unit;
    for (const auto& [suffix, u] : suffixes)
      if (name.size() >= suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
        unit = u;
        break;
      }
    if (f.type == FieldType::kNumber && !name.empty() && name != "steps_per_second") {
      EXPECT_EQ(unit, f.unit) << name;
    }
  }
}

// A harmonic run with a sensor: the headline period is the rig's estimator's.
TEST(Headline, HarmonicRunLeadsWithTheEstimatorsPeriod) {
  const RunSummary r = run_experiment(minimal_scene({{"world.duration", "8 s"}}), {});
  ASSERT_EQ(r.regime, Regime::kOscillates);
  ASSERT_TRUE(r.period && r.estimator && r.mu_k_recovered);
  // The headline is a measurement of the motion: the trajectory's own period within the
  // estimator's standard error (three of them) and its single-precision timing (0.05 %), and mu_k
  // from it the scene's through the paper's formula within the same.
  ASSERT_TRUE(r.period_trajectory);
  const double bound = 3.0 * r.estimator->period_std_error + 5e-4 * *r.period_trajectory;
  EXPECT_NEAR(*r.period, *r.period_trajectory, bound);
  EXPECT_NEAR(
      *r.mu_k_recovered,
      2.0 * std::numbers::pi * std::numbers::pi * r.spacing / (r.gravity * *r.period * *r.period),
      1e-12);
  EXPECT_EQ(r.mu_k_source, PeriodSource::kHallEstimator);
  EXPECT_FALSE(r.period_withheld.has_value());
  const nlohmann::json j = summary_json(r);
  EXPECT_EQ(j["period_s"], r.estimator->period);
  EXPECT_TRUE(j.contains("mu_k_estimator"));
}

// Without a sensor there is no estimator: its numbers are null, not 0, and mu_k comes from the
// trajectory's own period.
TEST(Headline, WithoutASensorTheEstimatorsNumbersAreNull) {
  Scene s = minimal_scene({{"world.duration", "8 s"}});
  s.sensor.reset();
  const RunSummary r = run_experiment(s, {});
  ASSERT_EQ(r.regime, Regime::kOscillates);
  EXPECT_FALSE(r.period.has_value());
  EXPECT_EQ(r.mu_k_source, PeriodSource::kTrajectory);
  const nlohmann::json j = summary_json(r);
  EXPECT_TRUE(j["period_s"].is_null());
  EXPECT_TRUE(j["period_std_s"].is_null());
  EXPECT_FALSE(j.contains("mu_k_estimator"));
  EXPECT_FALSE(j.contains("mu_k_err_worst"));
  ASSERT_TRUE(j["mu_k_recovered"].is_number());
  EXPECT_NEAR(j["mu_k_recovered_thick"].get<double>() / r.mu_k_set, 1.0, 1e-3);
}

// Started beyond the tipping amplitude, the plate lifts off a roller: its trajectory still
// crosses the centre at a steady rate, but the paper's model does not hold, so there is no period
// of any kind (neither the estimator's nor the trajectory's), and the run says why.
TEST(Headline, NoPeriodForARunThatIsNotHarmonic) {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  const Scene s = load_scene_file(
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme/amplitude-60pct.yaml", {},
      []() -> const PaperTable& { return table; });
  const RunSummary r = run_experiment(s, {});
  ASSERT_EQ(r.regime, Regime::kTips);
  EXPECT_FALSE(r.period || r.period_trajectory || r.mu_k_recovered || r.mu_k_estimator);
  ASSERT_TRUE(r.period_withheld.has_value());
  EXPECT_NE(r.period_withheld->find("tips"), std::string::npos);
  const nlohmann::json j = summary_json(r);
  for (const char* key : {"period_s", "period_trajectory_s", "mu_k_recovered", "error_vs_thick",
                          "trajectory_error_vs_thick"})
    EXPECT_TRUE(j[key].is_null()) << key;
}

}  // namespace
}  // namespace fl
