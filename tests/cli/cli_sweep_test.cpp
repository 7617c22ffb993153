// frictionlab sweep, merge and compare from the command line: a sweep killed with SIGKILL (or
// stopped with SIGINT) part-way and started again ends with the same bytes as an uninterrupted
// one; the same under mpirun; shards and merge; plots; exit status 2 for bad sweep files.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"

extern char** environ;

namespace fl {
namespace {

namespace fs = std::filesystem;

const std::string kExe = FRICTIONLAB_EXE;
const std::string kSource = FRICTIONLAB_TEST_SOURCE_DIR;

fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(FRICTIONLAB_TEST_BINARY_DIR) / "cli-sweep-test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name() / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

// A sweep file in a test folder, reading the minimal scene by its absolute path.
std::string write_sweep(const fs::path& dir, const std::string& axes, const std::string& duration) {
  fs::create_directories(dir);
  const fs::path file = dir / "sweep.yaml";
  std::ofstream(file) << "format: 1\nname: test\nscene: " << kSource
                      << "/scenes/minimal.yaml\nset:\n  world.duration: " << duration << "\naxes:\n"
                      << axes;
  return file.string();
}

// Twelve points of 20 simulated seconds: long enough to kill the sweep part-way.
const std::string kTwelve =
    "  - material: [lego, cardboard, plexiglas]\n"
    "  - key: rollers.spacing\n    values: [70 mm, 89 mm, 110 mm, 130 mm]\n";

test::CommandResult lab(const std::string& args) {
  return test::run_command(kExe + " " + args);
}

void expect_same_final_files(const fs::path& a, const fs::path& b) {
  for (const char* file : {"results.csv", "sweep.json"}) {
    const std::string text = test::read_text(a / file);
    EXPECT_FALSE(text.empty()) << a / file;
    EXPECT_TRUE(text == test::read_text(b / file))
        << file << " differs between " << a << " and " << b;
  }
}

std::size_t point_files(const fs::path& dir) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "points", ec))
    if (e.path().extension() == ".json") ++n;
  return n;
}

// Starts `frictionlab sweep` as a child process (output to /dev/null).
pid_t start_sweep(const std::vector<std::string>& args) {
  std::vector<std::string> storage{kExe, "sweep"};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, kExe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(rc, 0);
  return pid;
}

// Waits until the sweep has finished `n` points (or gives up after a minute).
bool wait_for_points(const fs::path& dir, std::size_t n) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (std::chrono::steady_clock::now() < deadline) {
    if (point_files(dir) >= n) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

TEST(CliSweep, KilledPartWayAndResumedGivesTheSameBytes) {
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kTwelve, "20 s");
  const fs::path reference = base / "reference", killed = base / "killed";
  const auto r = lab("sweep " + file + " -j 1 --out " + reference.string());
  ASSERT_EQ(r.status, 0) << r.err;

  const pid_t pid = start_sweep({file, "-j", "2", "--out", killed.string()});
  ASSERT_TRUE(wait_for_points(killed, 3));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const std::size_t done = point_files(killed);
  ASSERT_LT(done, 12u) << "the sweep finished before it could be killed";
  EXPECT_FALSE(fs::exists(killed / "results.csv"));

  // The same command again: skips the points done, finishes the rest.
  const auto again = lab("sweep " + file + " -j 2 --out " + killed.string() + " --json");
  ASSERT_EQ(again.status, 0) << again.err;
  const auto j = nlohmann::json::parse(again.out);
  EXPECT_EQ(j["resumed"].get<std::size_t>(), done);
  EXPECT_EQ(j["ran"].get<std::size_t>(), 12u - done);
  EXPECT_TRUE(j["complete"].get<bool>());
  expect_same_final_files(reference, killed);
}

TEST(CliSweep, SigintStopsCleanlyAndTheSweepResumes) {
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kTwelve, "20 s");
  const fs::path reference = base / "reference", stopped = base / "stopped";
  ASSERT_EQ(lab("sweep " + file + " -j 2 --out " + reference.string()).status, 0);
  const pid_t pid = start_sweep({file, "-j", "1", "--out", stopped.string()});
  ASSERT_TRUE(wait_for_points(stopped, 2));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_LT(point_files(stopped), 12u);
  ASSERT_EQ(lab("sweep " + file + " --out " + stopped.string()).status, 0);
  expect_same_final_files(reference, stopped);
}

TEST(CliSweep, MpiRanksWriteTheSameFileAsOneProcess) {
  if (!FRICTIONLAB_TEST_MPI) GTEST_SKIP() << "built without MPI";
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kTwelve, "4 s");
  const fs::path single = base / "single", ranks = base / "mpi";
  ASSERT_EQ(lab("sweep " + file + " -j 1 --out " + single.string()).status, 0);
  // As root, Open MPI's mpirun needs these; the sanitizers' leak check knows nothing of MPI's
  // lifetime allocations.
  const auto r = test::run_command(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=detect_leaks=0 " +
      std::string(FRICTIONLAB_TEST_MPIEXEC) + " -np 2 --oversubscribe " + kExe + " sweep " + file +
      " --out " + ranks.string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // rank 0 alone prints
  EXPECT_EQ(j["ranks"], 2);
  EXPECT_EQ(j["ran"], 12);
  expect_same_final_files(single, ranks);
  const auto timing = nlohmann::json::parse(test::read_text(ranks / "timing.json"));
  ASSERT_EQ(timing["ran_by_rank"].size(), 2u);
  EXPECT_EQ(timing["ran_by_rank"][0].get<int>() + timing["ran_by_rank"][1].get<int>(), 12);
}

TEST(CliSweep, ShardsAndMerge) {
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kTwelve, "2 s");
  ASSERT_EQ(lab("sweep " + file + " --out " + (base / "whole").string()).status, 0);
  std::string dirs;
  for (int k = 1; k <= 3; ++k) {
    const fs::path d = base / ("shard" + std::to_string(k));
    const auto r =
        lab("sweep " + file + " --shard " + std::to_string(k) + "/3 --out " + d.string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("this shard is done"), std::string::npos) << r.out;
    dirs += " " + d.string();
  }
  const auto m = lab("merge" + dirs + " --out " + (base / "merged").string());
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_NE(m.out.find("12 points; 12 ok"), std::string::npos) << m.out;
  expect_same_final_files(base / "whole", base / "merged");
  const auto partial =
      lab("merge " + (base / "shard1").string() + " --out " + (base / "partial").string());
  EXPECT_EQ(partial.status, 2);
  EXPECT_NE(partial.err.find("missing: 1, 2, 4, 5"), std::string::npos) << partial.err;
  EXPECT_EQ(lab("sweep " + file + " --shard 4/3").status, 2);
}

TEST(CliSweep, PlotsAreDrawn) {
  const fs::path base = folder("");
  const std::string file = write_sweep(
      base,
      "  - material: [lego, rigid-foam]\n  - {key: rollers.spacing, from: 60 mm, to: 120 mm, "
      "steps: 3}\n",
      "2 s");
  const auto r = lab("sweep " + file + " --plot --out " + (base / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* png : {"period-vs-spacing.png", "mu-recovered.png", "map.png"}) {
    EXPECT_TRUE(fs::exists(base / "out" / png)) << png;
    EXPECT_NE(r.out.find(png), std::string::npos) << r.out;
  }
}

TEST(CliSweep, CyclesAreCollectedAndPlottedAgainstTheRollersSpeed) {
  // The ramp's scene, shortened to 30 s: 400 rpm down to 100 rpm and back, two laws.
  const fs::path base = folder("");
  fs::create_directories(base);
  const std::string file = (base / "ramp.yaml").string();
  std::ofstream(file)
      << "format: 1\nname: ramp\nscene: " << kSource << "/scenes/roller-ramp.yaml\n"
      << "cycles: true\nset:\n  world.duration: 30 s\n  rollers.speed_ramp: [{at: 0 s, speed: "
         "400 rpm}, {at: 15 s, speed: 100 rpm}, {at: 30 s, speed: 400 rpm}]\n"
      << "axes:\n  - key: friction\n    name: law\n    values: [{mu_k: 0.29}, {mu_k: 0.29, "
         "mu_s: 0.348}]\n";
  const fs::path out = base / "out";
  const auto r = lab("sweep " + file + " -j 2 --plot --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  for (const char* name : {"00000000.csv", "00000001.csv"}) {
    const std::string csv = test::read_text(out / "cycles" / name);
    EXPECT_EQ(csv.rfind("start_s,period_s,amplitude_m,", 0), 0u) << name;
    // A 30 s run of 0.79 s periods: about 37 cycles, some going down, some up.
    const auto rows = std::count(csv.begin(), csv.end(), '\n') - 1;
    EXPECT_GT(rows, 30) << name;
    EXPECT_NE(csv.find(",down,"), std::string::npos) << name;
    EXPECT_NE(csv.find(",up,"), std::string::npos) << name;
  }
  EXPECT_TRUE(fs::exists(out / "cycles.png"));
  EXPECT_NE(r.out.find("cycles.png"), std::string::npos) << r.out;
  // A run writes the same cycles to cycles.csv as its sweep point.
  const fs::path run = base / "run";
  const auto single = lab("run " + kSource + "/scenes/roller-ramp.yaml --set world.duration=30s " +
                          "--set \"rollers.speed_ramp=[{at: 0 s, speed: 400 rpm}, {at: 15 s, "
                          "speed: 100 rpm}, {at: 30 s, speed: 400 rpm}]\" --set " +
                          "\"friction={mu_k: 0.29}\" --out " + run.string());
  ASSERT_EQ(single.status, 0) << single.err;
  EXPECT_EQ(test::read_text(run / "cycles.csv"), test::read_text(out / "cycles" / "00000000.csv"));
}

// Four points: one that runs, one whose 0.15 s step blows up (failed: a guard stops the run) and
// two whose spacing is not a length (invalid).
const std::string kFailing =
    "  - key: rollers.spacing\n    values: [89 mm, abc]\n"
    "  - key: world.time_step\n    values: [1 ms, 0.15 s]\n";

// The data rows of a results.csv, and the statuses of a sweep.json's rows, in point order.
std::size_t csv_rows(const fs::path& file) {
  const std::string text = test::read_text(file);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) - 1;
}
std::vector<std::string> statuses(const fs::path& file) {
  std::vector<std::string> out;
  const nlohmann::json sweep = nlohmann::json::parse(test::read_text(file));
  for (const auto& row : sweep["rows"]) out.push_back(row["status"].get<std::string>());
  return out;
}

TEST(CliSweep, PointsWithoutAResultExitWithStatusThreeAndEveryRowIsWritten) {
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kFailing, "2 s");
  const fs::path out = base / "out";
  const auto r = lab("sweep " + file + " -j 2 --plot --out " + out.string());
  EXPECT_EQ(r.status, 3) << r.err;
  // Drawn too, though no point gave a period (2 s runs are too short for one).
  EXPECT_TRUE(fs::exists(out / "map.png"));
  EXPECT_NE(r.err.find("frictionlab sweep: 3 of 4 points gave no result (1 failed, 2 invalid)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find((out / "results.csv").string()), std::string::npos) << r.err;
  // The progress line (stderr on a pipe: a line as points finish, the last at 4/4) tells the two
  // kinds apart as the summary does.
  const std::size_t last = r.err.find("4/4 points");
  ASSERT_NE(last, std::string::npos) << r.err;
  const std::string line = r.err.substr(last, r.err.find('\n', last) - last);
  EXPECT_NE(line.find(" left, 1 failed, 2 invalid"), std::string::npos) << line;
  EXPECT_NE(r.out.find("status: 1 failed, 2 invalid, 1 ok"), std::string::npos) << r.out;
  // The results are written whole: a row for every point, failed ones with their error.
  EXPECT_EQ(csv_rows(out / "results.csv"), 4u);
  EXPECT_EQ(statuses(out / "sweep.json"),
            (std::vector<std::string>{"ok", "failed", "invalid", "invalid"}));

  // Started again, every point is found done: the same results, the same status.
  const auto again = lab("sweep " + file + " --out " + out.string() + " --json");
  EXPECT_EQ(again.status, 3) << again.err;
  const auto j = nlohmann::json::parse(again.out);  // stdout stays one JSON object
  EXPECT_EQ(j["resumed"], 4);
  EXPECT_EQ(j.at("status").value("failed", 0), 1);
  EXPECT_EQ(j.at("status").value("invalid", 0), 2);
  EXPECT_NE(again.err.find("3 of 4 points gave no result"), std::string::npos) << again.err;
}

TEST(CliSweep, MergedShardsWithPointsWithoutAResultExitWithStatusThree) {
  const fs::path base = folder("");
  const std::string file = write_sweep(base, kFailing, "2 s");
  std::string dirs;
  for (int k = 1; k <= 2; ++k) {
    const fs::path d = base / ("shard" + std::to_string(k));
    // A shard that does not complete the sweep leaves the verdict to merge.
    const auto r =
        lab("sweep " + file + " --shard " + std::to_string(k) + "/2 --out " + d.string());
    EXPECT_EQ(r.status, 0) << r.err;
    dirs += " " + d.string();
  }
  const fs::path merged = base / "merged";
  const auto m = lab("merge" + dirs + " --out " + merged.string());
  EXPECT_EQ(m.status, 3) << m.err;
  EXPECT_NE(m.err.find("frictionlab merge: 3 of 4 points gave no result (1 failed, 2 invalid)"),
            std::string::npos)
      << m.err;
  EXPECT_EQ(csv_rows(merged / "results.csv"), 4u);
  EXPECT_EQ(statuses(merged / "sweep.json"),
            (std::vector<std::string>{"ok", "failed", "invalid", "invalid"}));
}

TEST(CliSweep, BadSweepFilesExitWithStatusTwo) {
  const fs::path base = folder("");
  fs::create_directories(base);
  std::ofstream(base / "bad.yaml") << "format: 1\nscene: " << kSource
                                   << "/scenes/minimal.yaml\naxes:\n  - {key: rollers.spaceing, "
                                      "values: [1 mm]}\n";
  const auto r = lab("sweep " + (base / "bad.yaml").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.yaml:4:5: error: axis rollers.spaceing"), std::string::npos) << r.err;
  EXPECT_EQ(lab("sweep /nonexistent.yaml").status, 2);
  EXPECT_EQ(lab("merge " + base.string()).status, 2);  // not a sweep folder
}

TEST(CliCompare, EveryRowOfTableOneIsReported) {
  const fs::path out = folder("out");
  const auto r = lab("compare --duration 5s --json --plot --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 15u);
  int room = 0, cold = 0;
  for (const auto& row : j["rows"]) {
    (row["temperature_k"].get<double>() > 200 ? room : cold) += 1;
    if (row["material"] == "flexible-foam" && row["temperature_k"].get<double>() > 200) {
      EXPECT_EQ(row["status"], "no oscillation");
      EXPECT_FALSE(row["reason"].get<std::string>().empty());
      EXPECT_TRUE(row["mu_k_refit"].is_null());
      continue;
    }
    EXPECT_EQ(row["status"], "compared") << row["material"];
    EXPECT_TRUE(row["mu_k_refit"].is_number()) << row["material"];
    EXPECT_NEAR(row["residual_sigma"].get<double>(),
                (row["period_simulated_s"].get<double>() - row["period_measured_s"].get<double>()) /
                    row["period_measured_err_s"].get<double>(),
                1e-12);
  }
  EXPECT_EQ(room, 10);
  EXPECT_EQ(cold, 5);
  for (const char* file : {"compare.csv", "compare.json", "compare.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const auto table = lab("compare --duration 3s --no-refit --out " + out.string());
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("Polyurethane flexible foam   300 K     0.13 +- 0.01  no oscillation"),
            std::string::npos)
      << table.out;
}

// compare --log: the example log of the paper's rig at 89 mm against the paper's rig, with the
// report, the traces and the plot written; options that read a log refused without one.
TEST(CliCompare, ALogAgainstItsSimulation) {
  const fs::path out = folder("log");
  const std::string log =
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/assets/examples/spacing-series/lego-l089.csv";
  const auto r = lab("compare --log " + log + " --json --plot --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // The example was simulated from this scene at mu_k 0.29: the refit finds it.
  EXPECT_NEAR(j["mu_k_refit"].get<double>(), 0.29, 1e-3);
  EXPECT_TRUE(j["disagreements"].empty()) << j["disagreements"];
  for (const char* file : {"compare-log.json", "compare-log-traces.json", "compare-log.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  test::CommandResult refused;
  // The paper's value for the sidecar's material (lego at 300 K: mu_k 0.29 +- 0.03) beside the
  // refit, the difference in combined standard errors computed here from the two.
  const double mu = j["mu_k_refit"], err = j["mu_k_refit_err_quadrature"];
  EXPECT_EQ(j["paper"]["key"], "lego");
  EXPECT_NEAR(j["paper"]["difference_standard_errors"].get<double>(),
              (mu - 0.29) / std::sqrt(err * err + 0.03 * 0.03), 1e-9);
  // A material named wins over the sidecar's; a table of rows names its own.
  const auto iron = lab("compare --log " + log + " --material iron --out " + out.string());
  ASSERT_EQ(iron.status, 0) << iron.err;
  EXPECT_NE(iron.out.find("Iron at 300 K: mu_k"), std::string::npos) << iron.out;
  EXPECT_NE(iron.out.find("the refitted mu_k is"), std::string::npos) << iron.out;
  refused = lab("compare --material lego --out " + out.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("--material and --temperature go with --log"), std::string::npos)
      << refused.err;
  refused = lab("compare --geometry one --out " + out.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("--geometry: error: --geometry, --columns, --rate and --time-unit say "
                             "how to read a log; they go with --log"),
            std::string::npos)
      << refused.err;
  refused = lab("compare --log " + log + " --measured x.csv --out " + out.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("give one"), std::string::npos) << refused.err;
}

// docs/students.md's worked example: the example spacing series estimated into a table, the table
// compared with the paper's rig it was simulated from. The thin mu_k each log reports falls with l
// (the thick plate's bias 2 mu_k h_c / l); the refit through the rig finds the truth, 0.29, in
// every row.
TEST(CliCompare, TheExampleSeriesRefitsToTheTruth) {
  const fs::path out = folder("series");
  const std::string series =
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/assets/examples/spacing-series";
  const auto table = lab("estimate " + series + " --out " + out.string());
  ASSERT_EQ(table.status, 0) << table.err;
  const auto r = lab("compare --measured " + (out / "estimates.csv").string() + " --json --out " +
                     out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 7u);
  double previous_thin = 1.0;
  for (const auto& row : rows) {
    EXPECT_EQ(row["status"], "compared") << row["label"];
    EXPECT_LT(row["mu_k_reported"].get<double>(), previous_thin) << row["label"];
    previous_thin = row["mu_k_reported"].get<double>();
    // The log's T is within a few standard errors (about 5e-5 T) of the scene's: mu_k within 1e-3.
    EXPECT_NEAR(row["mu_k_refit"].get<double>(), 0.29, 1e-3) << row["label"];
  }
  // fit reads the same table: the thick-plate line gives the truth, mu_k 0.29 and the paper's
  // rig's h_c 3.58 mm, far inside its errors (set by the 1 mm of each spacing). The simulated
  // periods follow the thick curve within 0.05 % (the spacing sweep's claim), which moves h_c by
  // at most about 0.1 mm here.
  const auto fit = lab("fit " + (out / "estimates.csv").string() + " --json");
  ASSERT_EQ(fit.status, 0) << fit.err;
  const auto j = nlohmann::json::parse(fit.out);
  EXPECT_NEAR(j["mu_k"].get<double>(), 0.29, 1e-3);
  EXPECT_NEAR(j["h_c_m"].get<double>(), 3.58e-3, 1e-4);
  EXPECT_EQ(j["rows"].size(), 7u);
}

}  // namespace
}  // namespace fl
