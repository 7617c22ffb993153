// Running sweeps: results bit-identical whatever the number of workers, failing points recorded
// without stopping the sweep, resume from the point files, interrupts, shards and merge.
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/paper_table_yaml.hpp"
#include "lab/sweep/sweep_run.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

const std::string kSweeps = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/sweeps";

const PaperTable& table() {
  static const PaperTable t = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  return t;
}
const PaperTableSource kPaper = []() -> const PaperTable& { return table(); };
const SceneInputs kInputs{kPaper, {}};

// Six short points: two materials x three spacings.
const std::string kSmall =
    "format: 1\nscene: ../minimal.yaml\n"
    "set:\n  world.duration: 8 s\n"
    "axes:\n"
    "  - material: [lego, cardboard]\n"
    "  - key: rollers.spacing\n    values: [70 mm, 89 mm, 120 mm]\n";

SweepSpec load(const std::string& text) {
  return load_sweep_text(text, "small.yaml", kSweeps, kInputs);
}

// A fresh folder per test (ctest runs tests in parallel).
fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(FRICTIONLAB_TEST_BINARY_DIR) / "sweep-run-test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name() / name;
  fs::remove_all(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

SweepOutcome run(const SweepSpec& spec, const fs::path& dir, int workers,
                 std::optional<Shard> shard = std::nullopt, const std::atomic<bool>* stop = nullptr,
                 std::function<void(const SweepProgress&)> progress = {}) {
  SweepRunOptions o;
  o.out_dir = dir.string();
  o.workers = workers;
  o.shard = shard;
  o.inputs = kInputs;
  o.stop = stop;
  o.progress = std::move(progress);
  return run_sweep(spec, o);
}

void expect_same_final_files(const fs::path& a, const fs::path& b) {
  for (const char* file : {"results.csv", "sweep.json"}) {
    const std::string text = read(a / file);
    EXPECT_FALSE(text.empty()) << a / file;
    EXPECT_EQ(text, read(b / file)) << file << " differs between " << a << " and " << b;
  }
}

TEST(SweepRun, OneAndTwoWorkersWriteTheSameBytes) {
  const SweepSpec spec = load(kSmall);
  const fs::path one = folder("j1"), two = folder("j2");
  const SweepOutcome a = run(spec, one, 1);
  const SweepOutcome b = run(spec, two, 2);
  EXPECT_TRUE(a.complete);
  EXPECT_TRUE(b.complete);
  EXPECT_EQ(a.ran, 6u);
  EXPECT_EQ(b.workers, 2);
  EXPECT_EQ(a.status.at("ok"), 6);
  expect_same_final_files(one, two);
  // A row per point in point order, the parameters and the seed in each.
  const std::string csv = read(one / "results.csv");
  EXPECT_EQ(csv.substr(0, 60), "index,material,rollers.spacing,seed,status,regime,period_s,p");
  EXPECT_NE(csv.find("\n0,lego,70 mm,1,ok,oscillates,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n5,cardboard,120 mm,1,ok,oscillates,"), std::string::npos) << csv;
  const nlohmann::json j = nlohmann::json::parse(read(one / "sweep.json"));
  EXPECT_EQ(j["points"], 6);
  EXPECT_EQ(j["rows"][4]["params"]["rollers.spacing"], "89 mm");
  EXPECT_EQ(j["rows"][4]["paper_material"], "cardboard");
  EXPECT_NEAR(j["rows"][4]["error_vs_thick"].get<double>(), 0.0, 5e-4);
  EXPECT_TRUE(fs::exists(one / "timing.json"));
  EXPECT_EQ(fs::exists(one / "points" / "00000005.json"), true);
}

// A seeds axis is the seed column: one column named seed, holding each point's seed.
TEST(SweepRun, ASeedsAxisIsTheSeedColumn) {
  const fs::path dir = folder("seeds");
  const SweepOutcome outcome =
      run(load("format: 1\nscene: ../minimal.yaml\nset: {world.duration: 1 s}\naxes:\n"
               "  - seeds: [3, 9]\n"),
          dir, 1);
  ASSERT_TRUE(outcome.complete);
  const std::string csv = read(dir / "results.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header.find("seed"), header.rfind("seed")) << header;
  EXPECT_EQ(csv.substr(csv.find('\n') + 1, 6), "0,3,ok");
}

TEST(SweepRun, FailingPointsAreRecordedAndTheSweepGoesOn) {
  const SweepSpec spec = load(
      "format: 1\nscene: ../minimal.yaml\nset:\n  world.duration: 2 s\n"
      "axes:\n"
      "  - key: rollers.spacing\n    values: [89 mm, 15 mm, abc]\n"
      "  - key: world.time_step\n    values: [1 ms, 0.15 s]\n");
  const fs::path dir = folder("out");
  const SweepOutcome o = run(spec, dir, 2);
  ASSERT_TRUE(o.complete);
  const nlohmann::json rows = nlohmann::json::parse(read(dir / "sweep.json"))["rows"];
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0]["status"], "ok");
  EXPECT_EQ(rows[0]["regime"], "oscillates");
  // The physics blows up at a 0.15 s step: a guard stops the run, recorded as failed.
  EXPECT_EQ(rows[1]["status"], "failed");
  EXPECT_NE(rows[1]["error"].get<std::string>().find("time step"), std::string::npos) << rows[1];
  // An impossible set-up and a bad value: invalid, with the loader's located message.
  EXPECT_EQ(rows[2]["status"], "invalid");
  EXPECT_NE(rows[2]["error"].get<std::string>().find("set rollers.spacing=15 mm"),
            std::string::npos)
      << rows[2]["error"];
  EXPECT_NE(rows[2]["error"].get<std::string>().find("overlap"), std::string::npos);
  EXPECT_EQ(rows[4]["status"], "invalid");
  EXPECT_NE(rows[4]["error"].get<std::string>().find("rollers.spacing"), std::string::npos);
  EXPECT_TRUE(rows[4]["period_s"].is_null());
  EXPECT_TRUE(rows[4]["seed"].is_null());
  EXPECT_EQ(o.status.at("ok"), 1);
  EXPECT_EQ(o.status.at("invalid"), 4);
  EXPECT_EQ(o.status.at("failed"), 1);
  // The error is quoted in the CSV (it holds commas and quotes).
  EXPECT_NE(read(dir / "results.csv").find(",\"set rollers.spacing=abc: error: "),
            std::string::npos);
  EXPECT_NE(read(dir / "results.csv").find("found \"\"abc\"\""), std::string::npos);
}

TEST(SweepRun, ResumesFromThePointFilesAndEndsWithTheSameBytes) {
  const SweepSpec spec = load(kSmall);
  const fs::path whole = folder("whole"), part = folder("part");
  run(spec, whole, 2);
  // A sweep that stopped after some points: their files are there, the final files not yet.
  fs::create_directories(part);
  fs::copy(whole / "plan.json", part / "plan.json");
  fs::create_directories(part / "points");
  for (const char* p : {"00000000.json", "00000003.json", "00000004.json"})
    fs::copy(whole / "points" / p, part / "points" / p);
  // A damaged point file (a disk that lost its tail) and a killed write's temporary file.
  std::ofstream(part / "points" / "00000005.json") << "{\"plan\": \"";
  std::ofstream(part / "points" / "00000001.json.tmp.Ab12Cd") << "{";
  const SweepOutcome o = run(spec, part, 2);
  EXPECT_EQ(o.resumed, 3u);
  EXPECT_EQ(o.ran, 3u);
  EXPECT_TRUE(o.complete);
  expect_same_final_files(whole, part);
  // Nothing left to do: the final files are written again, the same.
  const SweepOutcome again = run(spec, part, 1);
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(again.resumed, 6u);
  expect_same_final_files(whole, part);
}

TEST(SweepRun, AnInterruptFinishesTheRunningPointsAndResumes) {
  const SweepSpec spec = load(kSmall);
  const fs::path whole = folder("whole"), part = folder("part");
  run(spec, whole, 1);
  std::atomic<bool> stop{false};
  // Stop once the first point is in: one worker, so the rest are never started.
  const SweepOutcome o = run(spec, part, 1, std::nullopt, &stop, [&stop](const SweepProgress& p) {
    if (p.done >= 1) stop = true;
  });
  EXPECT_TRUE(o.interrupted);
  EXPECT_FALSE(o.complete);
  EXPECT_LT(o.ran, 6u);
  EXPECT_FALSE(fs::exists(part / "results.csv"));
  const SweepOutcome resumed = run(spec, part, 2);
  EXPECT_EQ(resumed.resumed, o.ran);
  EXPECT_TRUE(resumed.complete);
  expect_same_final_files(whole, part);
}

TEST(SweepRun, AFolderOfAnotherSweepIsRefusedUnlessFresh) {
  const fs::path dir = folder("out");
  run(load(kSmall), dir, 2);
  std::string other = kSmall;
  other.replace(other.find("120 mm"), 6, "121 mm");
  try {
    run(load(other), dir, 2);
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plan.json: error: this folder holds the results of "
                                         "another sweep (its axes or overrides differ)"),
              std::string::npos)
        << e.what();
  }
  SweepRunOptions o;
  o.out_dir = dir.string();
  o.inputs = kInputs;
  o.fresh = true;
  const SweepOutcome fresh = run_sweep(load(other), o);
  EXPECT_EQ(fresh.ran, 6u);
  EXPECT_NE(read(dir / "results.csv").find("121 mm"), std::string::npos);
}

TEST(SweepRun, ShardsMergeIntoTheSingleRun) {
  const SweepSpec spec = load(kSmall);
  const fs::path whole = folder("whole");
  run(spec, whole, 2);
  std::vector<std::string> shards;
  for (std::size_t k = 1; k <= 3; ++k) {
    const fs::path dir = folder("shard" + std::to_string(k));
    const SweepOutcome o = run(spec, dir, 1, Shard{k, 3});
    EXPECT_EQ(o.selected, 2u);
    EXPECT_FALSE(o.complete);
    EXPECT_FALSE(fs::exists(dir / "results.csv"));
    shards.push_back(dir.string());
  }
  // Missing a shard: refused, naming the points.
  try {
    merge_sweeps({shards[0], shards[2]}, folder("merged-partial").string());
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the folders hold 4 of the sweep's 6 points; missing: 1, "
                                         "4"),
              std::string::npos)
        << e.what();
  }
  const fs::path merged = folder("merged");
  const MergeOutcome m = merge_sweeps(shards, merged.string());
  EXPECT_EQ(m.points, 6u);
  expect_same_final_files(whole, merged);
  // Merging into one of the shards' own folders works too.
  merge_sweeps(shards, shards[1]);
  expect_same_final_files(whole, shards[1]);
  // Shards of another sweep do not mix.
  std::string other = kSmall;
  other.replace(other.find("70 mm"), 5, "71 mm");
  const fs::path stranger = folder("stranger");
  run(load(other), stranger, 1, Shard{1, 3});
  EXPECT_THROW(merge_sweeps({shards[0], stranger.string()}, folder("x").string()), InputError);
}

TEST(SweepRun, ShardsSharingOneFolderFinishIt) {
  const SweepSpec spec = load(kSmall);
  const fs::path whole = folder("whole"), shared = folder("shared");
  run(spec, whole, 2);
  EXPECT_FALSE(run(spec, shared, 1, Shard{1, 2}).complete);
  EXPECT_TRUE(run(spec, shared, 1, Shard{2, 2}).complete);
  expect_same_final_files(whole, shared);
}

// A sweep at a stated accuracy: each point steps at its own largest step (a whole fraction of a
// second, its predicted bias within 90 % of the accuracy) and lands within the accuracy of the
// thick-plate period and of the same point at the scene's 1 ms; asking for the trajectory's period
// only leaves the estimator's columns null; with them, the estimator's period meets it too.
TEST(SweepRun, AnAccuracySweepStepsEachPointAtItsOwnStepAndMeetsTheAccuracy) {
  const std::string axes =
      "set:\n  world.duration: 20 s\n  plate.length: 300 mm\n  plate.offset: 10 mm\n"
      "  sensor.position: [105 mm, 0 mm, 15 mm]\n"
      "axes:\n"
      "  - material: [cardboard, rigid-foam]\n"
      "  - key: rollers.spacing\n    values: [45 mm, 89 mm, 180 mm]\n";
  const std::string head = "format: 1\nscene: ../minimal.yaml\n";
  const SweepSpec fixed = load(head + axes);
  const SweepSpec hall = load(head + "accuracy: 0.01%\n" + axes);
  const SweepSpec trajectory = load(head + "accuracy: 0.01%\nperiod: trajectory\n" + axes);
  const auto rows_of = [&](const SweepSpec& spec, const std::string& name) {
    const fs::path dir = folder(name);
    EXPECT_TRUE(run(spec, dir, 2).complete);
    return nlohmann::json::parse(read(dir / "sweep.json"))["rows"];
  };
  const nlohmann::json at_1ms = rows_of(fixed, "fixed");
  const nlohmann::json with_hall = rows_of(hall, "hall");
  const nlohmann::json without = rows_of(trajectory, "trajectory");
  ASSERT_EQ(without.size(), 6u);
  std::set<double> steps;
  int refused = 0;
  for (std::size_t i = 0; i < without.size(); ++i) {
    const nlohmann::json& row = without[i];
    const std::string where = row["params"].dump();
    ASSERT_EQ(row["status"], "ok") << where << row["error"];
    EXPECT_EQ(row["regime"], "oscillates") << where;
    EXPECT_EQ(row["time_step_basis"], "integrator bias") << where;
    EXPECT_TRUE(at_1ms[i]["time_step_basis"].is_null()) << where;
    // The step: 1/N s, its bias within the integrator's 90 % of 1e-4, and 1/(N-1) s beyond it.
    const double dt = row["time_step_s"].get<double>();
    const double n = std::round(1.0 / dt);
    EXPECT_NEAR(1.0 / dt, n, 1e-9) << where;
    const double omega = 2.0 * std::numbers::pi / row["period_thick_s"].get<double>();
    EXPECT_LE(std::pow(omega * dt, 2) / 24.0, 0.9e-4) << where;
    EXPECT_GT(std::pow(omega / (n - 1.0), 2) / 24.0, 0.9e-4) << where;
    steps.insert(dt);
    // Within the accuracy of theory and of the fixed-step sweep's point.
    const double t = row["period_trajectory_s"].get<double>();
    EXPECT_LT(std::fabs(t / row["period_thick_s"].get<double>() - 1.0), 1e-4) << where;
    EXPECT_LT(std::fabs(t / at_1ms[i]["period_trajectory_s"].get<double>() - 1.0), 1e-4) << where;
    // No Hall signal: the estimator's period is not measured, mu_k comes from the trajectory.
    EXPECT_TRUE(row["period_s"].is_null()) << where;
    EXPECT_TRUE(row["periods_used"].is_null()) << where;
    EXPECT_NEAR(row["mu_k_recovered_thick"].get<double>(), row["mu_k_set"].get<double>(),
                2e-4 * row["mu_k_set"].get<double>())
        << where;
    // With the Hall signal: a step no coarser (the sensor's error takes its share of the
    // accuracy), and the estimator's period within the accuracy as well; or, where the sensor's
    // error alone would take more than its share (cardboard's slow pulses at 180 mm, 12 periods),
    // the point refused saying so.
    if (with_hall[i]["status"] == "failed") {
      EXPECT_NE(with_hall[i]["error"].get<std::string>().find(
                    "the rig's estimator times each turning point"),
                std::string::npos)
          << where << with_hall[i]["error"];
      ++refused;
      continue;
    }
    ASSERT_EQ(with_hall[i]["status"], "ok") << where << with_hall[i]["error"];
    EXPECT_LE(with_hall[i]["time_step_s"].get<double>(), dt) << where;
    ASSERT_TRUE(with_hall[i]["period_s"].is_number()) << where;
    EXPECT_LT(std::fabs(with_hall[i]["period_s"].get<double>() /
                            with_hall[i]["period_thick_s"].get<double>() -
                        1.0),
              1e-4)
        << where;
  }
  EXPECT_EQ(refused, 1);
  // Each point its own step: they span the grid's frequencies.
  EXPECT_EQ(steps.size(), 6u);
}

}  // namespace
}  // namespace fl
