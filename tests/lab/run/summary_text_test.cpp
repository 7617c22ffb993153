// The text summary's lines (lab/run/summary_text.hpp) against the declaration of a run's fields
// (lab/run/summary_fields.hpp): each line shows declared fields, every field summary.json carries
// is shown by a line or left out with a reason, and over runs of many kinds a line is printed only
// when a field it shows was measured (not null in summary.json).
#include "lab/run/summary_text.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "lab/run/summary_fields.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

std::set<std::string> json_keys() {
  std::set<std::string> keys;
  for (const SummaryField& f : summary_fields())
    if (f.json != nullptr) keys.insert(f.json);
  return keys;
}

TEST(SummaryText, EveryLineShowsDeclaredFieldsUnderItsOwnLabel) {
  const std::set<std::string> keys = json_keys();
  std::set<std::string> labels;
  for (const SummaryLine& line : summary_lines()) {
    EXPECT_NE(std::string(line.label), "");
    EXPECT_TRUE(labels.insert(line.label).second) << line.label;
    EXPECT_FALSE(line.shows.empty()) << line.label;
    for (const char* key : line.shows)
      EXPECT_TRUE(keys.contains(key)) << line.label << " shows " << key << ", not a summary key";
  }
}

TEST(SummaryText, EverySummaryKeyIsShownOrLeftOutWithAReason) {
  std::set<std::string> shown;
  for (const SummaryLine& line : summary_lines())
    for (const char* key : line.shows) shown.insert(key);
  std::set<std::string> omitted;
  for (const TextOmission& o : summary_text_omissions()) {
    EXPECT_NE(std::string(o.why), "") << o.key;
    EXPECT_FALSE(shown.contains(o.key)) << o.key << " is shown and said to be left out";
    omitted.insert(o.key);
  }
  for (const std::string& key : json_keys())
    EXPECT_TRUE(shown.contains(key) || omitted.contains(key))
        << key << ": no line shows it and it is not said to be left out (summary_text.cpp)";
}

// Runs that reach many of the lines: plain, driven with the paper's values, stick-slip, warming,
// a fast clock, run-out, a plate sliding sideways, one tipping, a clipped amplitude, no restoring
// force, a tilted rig, skewed rollers and one without a sensor; 8 s each, long enough for the
// estimator's periods.
std::vector<RunSummary> runs_of_many_kinds() {
  std::vector<RunSummary> runs;
  for (const char* name :
       {"minimal.yaml", "paper-rig.yaml", "extreme/stribeck-drop.yaml",
        "imperfect/rollers-warming.yaml", "imperfect/clock-fast.yaml", "imperfect/runout.yaml",
        "imperfect/plate-sideways.yaml", "extreme/amplitude-60pct.yaml",
        "extreme/roller-200rpm.yaml", "extreme/rollers-outward.yaml", "extreme/mu-50.yaml"}) {
    const std::vector<SceneOverride> shorter{{"world.duration", "8 s"}};
    runs.push_back(run_experiment(test::scene_file(name, shorter), {}));
  }
  runs.push_back(run_experiment(
      test::scene_file("minimal.yaml", std::vector<SceneOverride>{{"world.duration", "8 s"},
                                                                  {"world.tilt", "2 deg"}}),
      {}));
  runs.push_back(run_experiment(
      test::scene_file("minimal.yaml", std::vector<SceneOverride>{{"world.duration", "8 s"},
                                                                  {"rollers.skew", "0.2 deg"}}),
      {}));
  const std::vector<SceneOverride> bare{{"world.duration", "8 s"}};
  runs.push_back(run_experiment(test::minimal_without_sensor(bare), {}));
  return runs;
}

TEST(SummaryText, ALineIsPrintedOnlyWhenAFieldItShowsWasMeasured) {
  std::set<std::string> printed;
  for (const RunSummary& run : runs_of_many_kinds()) {
    const nlohmann::json json = summary_json(run);
    for (const SummaryLine& line : summary_lines()) {
      if (!line.text(run)) {
        EXPECT_FALSE(line.always) << run.scene << ": \"" << line.label << "\" not printed";
        continue;
      }
      printed.insert(line.label);
      if (line.always) continue;  // it says so when nothing was measured
      bool measured = false;
      for (const char* key : line.shows) {
        const auto at = json.find(key);
        measured = measured || (at != json.end() && !at->is_null());
      }
      EXPECT_TRUE(measured) << run.scene << ": \"" << line.label
                            << "\" printed with every field it shows null";
    }
  }
  // The runs reach every line but those of an interruption (Ctrl-C: tests/cli), an estimator at
  // odds with the trajectory and an amplitude that grows or decays exponentially.
  const std::set<std::string> out_of_reach = {"INTERRUPTED", "WARNING", "amplitude e-folding"};
  for (const SummaryLine& line : summary_lines())
    EXPECT_TRUE(printed.contains(line.label) || out_of_reach.contains(line.label))
        << "no run printed \"" << line.label << "\"";
}

}  // namespace
}  // namespace fl
