// The request layer every front end goes through (lab/request): fields named in messages and
// spelled by each front end, problems gathered by field, one exit status per outcome, and a run
// request refused by field before any work.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "io/field_ref.hpp"
#include "lab/logs/estimate_fields.hpp"
#include "lab/request/compare_request.hpp"
#include "lab/request/estimate_request.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/run_request.hpp"
#include "lab/request/study_requests.hpp"

namespace fl {
namespace {

std::string flag(const FieldMention& m) {
  return "--" + m.path + (m.value ? " " + *m.value : std::string());
}

TEST(FieldRef, AMentionIsSpelledByTheFrontEndAndReadBack) {
  const std::string text = "give " + field_ref("geometry", "pair") + " or " + field_ref("plot");
  EXPECT_TRUE(mentions_field(text));
  EXPECT_EQ(spell_fields(text, flag), "give --geometry pair or --plot");
  EXPECT_EQ(plain_fields(text), "give geometry pair or plot");
  const auto m = parse_field_ref(field_ref("set", "friction.mu_k=0.3"));
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->path, "set");
  EXPECT_EQ(m->value, "friction.mu_k=0.3");  // the first '=' ends the path
  EXPECT_FALSE(mentions_field(spell_fields(text, flag)));
  EXPECT_EQ(spell_fields("no field here", flag), "no field here");
}

TEST(FieldRef, AFieldLocationIsTheMentionBeforeTheMessage) {
  const InputError e(SourceLocation::of_field("video", "x.avi"), "expected .mp4");
  EXPECT_EQ(spell_fields(e.what(), flag), "--video x.avi: error: expected .mp4");
  EXPECT_EQ(e.where().field, "video");
  EXPECT_TRUE(e.where().file.empty());
}

TEST(FieldChecks, EveryProblemIsGatheredByItsField) {
  FieldChecks checks;
  EXPECT_DOUBLE_EQ(checks.quantity(QuantityInput{"89 mm"}, Dimension::kLength, "spacing"), 0.089);
  EXPECT_DOUBLE_EQ(checks.quantity(QuantityInput{0.5}, Dimension::kLength, "h_c"), 0.5);
  EXPECT_TRUE(checks.ok());
  checks.quantity(QuantityInput{"89 kg"}, Dimension::kLength, "spacing_err");
  checks.positive(QuantityInput{"-1 m/s^2"}, Dimension::kAcceleration, "gravity", "g");
  EXPECT_TRUE(checks.has("spacing_err"));
  EXPECT_TRUE(checks.has("gravity"));
  EXPECT_FALSE(checks.has("spacing"));
  try {
    checks.throw_if_any();
    FAIL() << "two problems were not thrown";
  } catch (const RequestError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_EQ(e.where().field, "spacing_err");
    const std::string text = spell_fields(e.what(), flag);
    EXPECT_NE(text.find("--spacing_err: error: expected a length"), std::string::npos) << text;
    EXPECT_NE(text.find("--gravity: error: expected g as a finite positive acceleration"),
              std::string::npos)
        << text;
  }
}

TEST(FieldChecks, APlainNumberOfMetresIsSaidAloud) {
  FieldChecks checks;
  EXPECT_DOUBLE_EQ(checks.quantity(QuantityInput{"89"}, Dimension::kLength, "spacing"), 89.0);
  ASSERT_EQ(checks.warnings().size(), 1u);
  EXPECT_EQ(spell_fields(checks.warnings().front(), flag),
            "--spacing 89 read as 89 m (a plain number is SI); write 89mm for millimetres");
  EXPECT_TRUE(checks.ok());
}

TEST(Outcome, EachEndingHasOneExitStatus) {
  EXPECT_EQ(exit_status(Outcome::kDone), 0);
  EXPECT_EQ(exit_status(Outcome::kIncomplete), 1);
  EXPECT_EQ(exit_status(Outcome::kBadInput), 2);
  EXPECT_EQ(exit_status(Outcome::kFailed), 3);
  EXPECT_EQ(exit_status(Outcome::kInterrupted, 2), 130);
  EXPECT_EQ(exit_status(Outcome::kInterrupted, 15), 143);
  EXPECT_EQ(worse(Outcome::kFailed, Outcome::kIncomplete), Outcome::kFailed);
  EXPECT_EQ(worse(Outcome::kDone, Outcome::kInterrupted), Outcome::kInterrupted);
}

RunRequest minimal_request() {
  RunRequest r;
  r.scene.file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
  r.scene.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
  return r;
}

TEST(RunRequest, WhatShapesFramesWithoutFramesIsRefusedFieldByField) {
  RunRequest r = minimal_request();
  r.size = FrameSizeInput{"640x480"};
  r.fps = 10;
  r.camera = "top";
  try {
    prepare_run(r);
    FAIL() << "frame fields without frames were taken";
  } catch (const RequestError& e) {
    ASSERT_EQ(e.problems().size(), 3u);
    EXPECT_EQ(e.problems()[0].field, "size");
    EXPECT_EQ(e.problems()[1].field, "fps");
    EXPECT_EQ(e.problems()[2].field, "camera");
  }
}

TEST(RunRequest, TheAccuracyPicksAStepOfTheFormOneOverN) {
  RunRequest r = minimal_request();
  r.accuracy = QuantityInput{"0.01%"};
  r.duration = QuantityInput{"1 s"};
  const PreparedRun prepared = prepare_run(r);
  ASSERT_TRUE(prepared.chosen_time_step.has_value());
  EXPECT_DOUBLE_EQ(prepared.rig->world.time_step, *prepared.chosen_time_step);
  const double n = 1.0 / *prepared.chosen_time_step;
  EXPECT_NEAR(n, std::round(n), 1e-9);
  ASSERT_TRUE(prepared.chosen_bias.has_value());
  EXPECT_LE(std::fabs(*prepared.chosen_bias), 1e-4);
  EXPECT_DOUBLE_EQ(prepared.rig->world.duration, 1.0);
}

// A run whose files the disk cannot hold is refused before it starts, saying how much they need:
// 27 hours of 0.1 ms steps make up to 270 GB of trajectory.csv.
TEST(RunRequest, FilesTheDiskCannotHoldAreRefusedBeforeTheRun) {
  RunRequest r = minimal_request();
  r.duration = QuantityInput{"99000 s"};
  r.set = {"world.time_step=0.1ms"};
  r.out = (std::filesystem::temp_directory_path() / "frictionlab-request-disk").string();
  const std::filesystem::space_info space =
      std::filesystem::space(std::filesystem::temp_directory_path());
  if (space.available > 272e9) GTEST_SKIP() << "this disk holds even 272 GB";
  try {
    prepare_run(r);
    FAIL() << "a run of 272 GB of files was taken";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.where().field, "out");
    const std::string m = e.what();
    EXPECT_NE(m.find("expected a folder with room for the run's files, up to 274 GB for 9.9e+04 "
                     "s of steps and samples, found "),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("B free there"), std::string::npos) << m;
  }
  std::filesystem::remove_all(r.out);
}

TEST(RunRequest, AStepTheRunCannotTakeIsRefusedAtTheAccuracy) {
  // A rig without a sensor: the trajectory's period alone, whose step only the accuracy sizes.
  RunRequest r = minimal_request();
  r.scene.file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme/mu-1.yaml";
  r.accuracy = QuantityInput{1e-17};
  try {
    prepare_run(r);
    FAIL() << "a run of more than 1e9 steps was taken";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.where().field, "accuracy");
    EXPECT_NE(std::string(e.what()).find("more than 1e9"), std::string::npos) << e.what();
  }
}

// A long job asked to stop (Ctrl-C in a front end) keeps what it finished and says so. Each stop
// here comes at a point of the job's own progress, not of the clock.
std::string temp_out(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("frictionlab-request-" + name + "-" + std::to_string(::getpid())))
      .string();
}

long file_lines(const std::string& path) {
  std::ifstream in(path);
  long n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(JobControl, ACompareAskedToStopKeepsTheRowsDone) {
  CompareRequest r;
  r.scene = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/paper-rig.yaml";
  r.assets = FRICTIONLAB_TEST_ASSET_DIR;
  r.duration = QuantityInput{"3 s"};
  r.jobs = 1;
  r.out = temp_out("compare");
  std::atomic<bool> stop{false};
  // Asked to stop once two rows are done: no row after those running then is simulated.
  const CompareRequestResult result = compare_measurements(
      r, [&stop](std::size_t done, std::size_t) { stop = stop || done >= 2; },
      JobControl{&stop, {}});
  ASSERT_TRUE(result.table.has_value());
  const std::vector<CompareRow>& rows = result.table->rows;
  ASSERT_EQ(rows.size(), 15u);
  EXPECT_EQ(rows[0].status, "compared");
  EXPECT_EQ(rows[1].status, "compared");
  EXPECT_EQ(rows.back().status, "interrupted");
  EXPECT_GE(result.table->rows_interrupted(), 12);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(result.outcome(), Outcome::kInterrupted);
  EXPECT_EQ(file_lines(r.out + "/compare.csv"), 16);
  std::filesystem::remove_all(r.out);
}

TEST(JobControl, AnAccuracyStudyAskedToStopKeepsItsFinishedPoints) {
  AccuracyRequest r;
  r.scene.file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
  r.scene.asset_dir = FRICTIONLAB_TEST_ASSET_DIR;
  r.out = temp_out("accuracy");
  std::atomic<bool> stop{false};
  int polls = 0;
  // Every 1000 steps a poll: stop after 60 (the first points at 1/120 s and 1/240 s take 1 and 2).
  const AccuracyResult result = study_accuracy(r, JobControl{&stop, [&] { stop = ++polls >= 60; }});
  EXPECT_TRUE(result.study.interrupted);
  EXPECT_EQ(result.outcome(), Outcome::kInterrupted);
  ASSERT_GE(result.study.points.size(), 2u);
  EXPECT_LT(result.study.points.size(), 28u);
  EXPECT_DOUBLE_EQ(result.study.points[0].time_step, 1.0 / 120);
  EXPECT_TRUE(result.study.points[0].valid);
  EXPECT_EQ(file_lines(r.out + "/accuracy.csv"), static_cast<long>(result.study.points.size()) + 1);
  std::filesystem::remove_all(r.out);
}

TEST(JobControl, AStabilityCatalogueAskedToStopBeforeItStartsRunsNoCase) {
  StabilityRequest r;
  r.dir = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme";
  r.assets = FRICTIONLAB_TEST_ASSET_DIR;
  r.jobs = 2;
  std::atomic<bool> stop{true};
  const StabilityResult result = study_stability(r, JobControl{&stop, {}});
  EXPECT_TRUE(result.rows.empty());
  EXPECT_EQ(result.not_run, 28);
  EXPECT_EQ(result.outcome(), Outcome::kInterrupted);
}

// A live capture's port settings are checked by the request, by field, whichever front end asks:
// a baud rate a port cannot take, a capture of no duration.
TEST(EstimateRequest, ALiveCapturesBaudAndDurationAreCheckedByField) {
  EstimateRequest r;
  r.follow_port = "/dev/ttyACM0";
  r.follow_baud = QuantityInput{"1.5"};
  r.follow_duration = QuantityInput{"0 s"};
  try {
    prepare_estimate(r);
    FAIL() << "a baud rate of 1.5 was taken";
  } catch (const RequestError& e) {
    ASSERT_EQ(e.problems().size(), 2u);
    EXPECT_EQ(e.problems()[0].field, "follow.baud");
    EXPECT_NE(e.problems()[0].message.find("expected a whole baud rate from 1 to 4000000"),
              std::string::npos);
    EXPECT_EQ(e.problems()[1].field, "follow.duration");
  }
  r.follow_baud = QuantityInput{static_cast<double>(kFirmwareBaud)};
  r.follow_duration = QuantityInput{"30 s"};
  EXPECT_DOUBLE_EQ(prepare_estimate(r).follow_baud, 250000.0);
}

// One log's answer (what `estimate --json` prints and Python's json() gives) holds exactly the keys
// the declaration names (lab/logs/estimate_fields.hpp), those the request adds included: a key
// added anywhere without its line there fails here.
TEST(EstimateRequest, OneLogsAnswerHoldsExactlyTheDeclaredKeys) {
  std::set<std::string> declared;
  for (const EstimateField& f : estimate_fields()) EXPECT_TRUE(declared.insert(f.json).second);
  EstimateRequest r;
  r.logs = {std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
            "/assets/examples/spacing-series/lego-l089.csv"};
  r.mc = 20;
  const nlohmann::json answer = estimate_one_log(prepare_estimate(r)).json();
  std::set<std::string> keys;
  for (auto it = answer.begin(); it != answer.end(); ++it) keys.insert(it.key());
  for (const std::string& key : keys) EXPECT_TRUE(declared.contains(key)) << key << ": undeclared";
  // raw_log is a live capture's (the front end's --follow adds it); every other key is here.
  for (const std::string& key : declared)
    EXPECT_TRUE(keys.contains(key) || key == "raw_log") << key << ": declared, not in the answer";
}

}  // namespace
}  // namespace fl
