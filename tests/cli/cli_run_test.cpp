// frictionlab run and accuracy: the JSON summary's keys, the output files and their
// determinism, --set, --accuracy, and exit status 2 for bad scenes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;
const std::string kMinimal = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
// A rig without a sensor (mu_k = 1): the trajectory's period alone.
const std::string kMuOne = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme/mu-1.yaml";
// Each test its own folder: ctest runs them in parallel.
std::filesystem::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::filesystem::path(FRICTIONLAB_TEST_BINARY_DIR) /
         ("cli-run-" + std::string(info->name()));
}

test::CommandResult lab(const std::string& args) {
  return test::run_command(kExe + " " + args);
}

TEST(CliRun, JsonHasEveryDocumentedKey) {
  const auto r = lab("run " + kMinimal + " --duration 5s --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"period_s", "period_std_s", "periods_used", "mu_k_set", "mu_k_recovered", "period_thin_s",
        "period_thick_s", "h_c_m", "spacing_m", "amplitude_start_m", "amplitude_end_m",
        "slip_margin", "regime", "wall_s", "real_time_factor", "steps_per_second"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["regime"], "oscillates");
  EXPECT_NEAR(j["period_s"].get<double>() / j["period_thick_s"].get<double>(), 1.0, 5e-4);
  EXPECT_DOUBLE_EQ(j["mu_k_set"].get<double>(), 0.29);
}

TEST(CliRun, OutputsAreWrittenAndBitIdenticalAcrossRuns) {
  std::filesystem::remove_all(test_dir());
  for (const char* name : {"a", "b"}) {
    const auto r = lab("run " + kMinimal + " --duration 3s --out " + (test_dir() / name).string());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const char* file : {"summary.json", "hall.csv", "trajectory.csv"}) {
    const std::string a = test::read_text(test_dir() / "a" / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, test::read_text(test_dir() / "b" / file)) << file;
  }
  EXPECT_TRUE(std::filesystem::exists(test_dir() / "a" / "timing.json"));
  // The Hall log is what `frictionlab estimate` reads.
  EXPECT_EQ(test::read_text(test_dir() / "a" / "hall.csv").substr(0, 9), "t_us,adc\n");
  std::filesystem::remove_all(test_dir());
}

TEST(CliRun, SetOverridesAndAccuracyChoosesTheStep) {
  const auto r = lab("run " + kMuOne + " --set friction.mu_k=1.0 --accuracy 0.001% --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["mu_k_set"].get<double>(), 1.0);
  // The largest 1/N s step with |bias| <= 90 % of 1e-5 (the integrator's share): mu_k = 1 needs
  // about 0.96 ms (N = 1040), not the scene's 1 ms; one N less would pass 0.9e-5 by 0.2 %.
  EXPECT_LE(std::fabs(j["predicted_integrator_bias"].get<double>()), 0.9e-5);
  EXPECT_GT(std::fabs(j["predicted_integrator_bias"].get<double>()), 0.89e-5);
  EXPECT_NE(j["time_step_s"].get<double>(), 1e-3);
}

TEST(CliRun, BadScenesExitWithStatusTwo) {
  std::filesystem::create_directories(test_dir());
  const auto write = [](const std::string& name, const std::string& text) {
    std::ofstream(test_dir() / name) << text;
    return (test_dir() / name).string();
  };
  struct Case {
    std::string args;
    std::string message;
  };
  for (const Case& c : {
           Case{"run /nonexistent.yaml", "no such file"},
           Case{"run " + write("empty.yaml", ""), "the file is empty"},
           Case{"run " + write("notyaml.yaml", "a: [1, 2\n"), "not valid YAML"},
           Case{"run " + write("typo.yaml", "format: 1\nfriction: {mu_k: 0.3}\nplat: {}\n"),
                "did you mean 'plate'?"},
           Case{"run " + kMinimal + " --set plate.thickness=5kg",
                "--set plate.thickness=5kg: error:"},
           Case{"run " + kMinimal + " --set plate.thickness", "expected key.path=value"},
           Case{"run " + kMinimal + " --duration 5m", "--duration: error: expected a time"},
           Case{"run " + kMinimal + " --set friction.mu_k=10 --set plate.thickness=10mm",
                "no oscillation exists"},
           Case{"accuracy /nonexistent.yaml", "no such file"},
       }) {
    const auto r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
  }
  std::filesystem::remove_all(test_dir());
}

// Nonsense is refused before any work: a run of no step, a step --accuracy would take past the
// step limit, output paths that cannot be written, keys compare sets itself. Each exits 2 with a
// located message and writes nothing.
TEST(CliRun, NonsenseIsRefusedBeforeAnyWork) {
  std::filesystem::create_directories(test_dir());
  const std::string file = (test_dir() / "a-file").string();
  std::ofstream(file) << "x";
  struct Case {
    std::string args;
    std::string message;
  };
  for (const Case& c : {
           Case{"run " + kMinimal + " --duration 0.5ms",
                "world.duration: must be at least one step of world.time_step"},
           Case{"run " + kMinimal + " --set world.time_step=0.3s",
                "world.time_step: expected a step that resolves the oscillation"},
           Case{"run " + kMinimal + " --accuracy 0.001%",
                "--accuracy 0.001%: error: the rig's estimator times each turning point to"},
           Case{"run " + kMuOne + " --accuracy 1e-20",
                "--accuracy 1e-20: error: expected a time step the run can take"},
           Case{"run " + kMinimal + " --video " + test_dir().string(),
                "--video " + test_dir().string() +
                    ": error: expected a place this command can "
                    "write, found a folder"},
           Case{"run " + kMinimal + " --out " + file, "found a file"},
           Case{"run " + kMinimal + " --still " + file + "/x.png", "is a file"},
           Case{"run " + kMinimal + " --plot", "--plot: error: expected --out as well"},
           Case{"accuracy " + kMinimal + " --out " + file,
                "--out " + file + ": error: expected a place"},
           Case{"stability --only mu-1 --out " + file, "found a file"},
           Case{"sweep " + std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                    "/scenes/sweeps/spacing.yaml --out " + file,
                "found a file"},
           Case{"compare --out " + file, "found a file"},
           Case{"estimate " + std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                    "/tests/data/logs/clean.csv --plot " + file + "/x.png",
                "--plot " + file + "/x.png: error: expected a place this command can write"},
           // A folder nothing can be written into, for root as well (/proc): refused before the
           // work, not after it.
           Case{"run " + kMinimal + " --still /proc/x.png",
                "--still /proc/x.png: error: expected a place this command can write, found a "
                "folder nothing can be written into"},
           Case{"run " + kMinimal + " --video /proc/x.mp4", "--video /proc/x.mp4: error:"},
           Case{"analytic --material lego --mc 1000 --plot /proc/x.png",
                "--plot /proc/x.png: error:"},
           // A title no card shows legibly.
           Case{"run " + kMinimal + " --video " + file + ".gif --title " + std::string(201, 'a'),
                "--title: error: expected a title of at most 200 characters"},
           // The still is a PNG, and its name says so.
           Case{"run " + kMinimal + " --still " + file + ".jpg",
                "--still: error: expected a .png file (the still is a PNG image), found \".jpg\""},
           Case{"compare --set friction.mu_k=0.3",
                "--set friction.mu_k=0.3: error: expected a key compare leaves to the scene"},
           Case{"compare --set world.duration=2s", "use --duration instead"},
       }) {
    const auto r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(r.out.find("frictionlab run:"), std::string::npos) << c.args;
  }
  // A plain length of metres where millimetres were meant: 1.5 m is a bench's and taken as
  // given; 89 m is none, and refused, saying how it was read.
  const auto warned = lab("analytic --spacing 1.5 --mu-k 0.3");
  EXPECT_EQ(warned.status, 0) << warned.err;
  const auto spacing = lab("analytic --spacing 89 --mu-k 0.3");
  EXPECT_EQ(spacing.status, 2);
  EXPECT_NE(spacing.err.find("so 89 was read as 89 m; write 89mm for millimetres"),
            std::string::npos)
      << spacing.err;
  EXPECT_EQ(spacing.err.find("warning:"), std::string::npos) << spacing.err;
  std::filesystem::remove_all(test_dir());
}

// What the run did not measure is null, and a fallback says it is one: a sensor the magnets never
// reach gives no period, no spread and no estimator mu_k, and mu_k from the trajectory with its
// source named; a scene without a sensor has no estimator counts.
// An option a command would ignore is an error, before any work.
TEST(CliRun, AnOptionTheCommandWouldIgnoreIsRefused) {
  struct Case {
    std::string args;
    std::string message;
  };
  for (const Case& c : {
           Case{"run " + kMinimal + " --camera top", "--camera: error: this shapes the frames"},
           Case{"run " + kMinimal + " --fps 10", "--fps: error: this shapes the frames"},
           Case{"run " + kMinimal + " --size 640x480", "--size: error:"},
           Case{"run " + kMinimal + " --gl osmesa", "--gl: error:"},
           Case{"run " + kMinimal + " --slow-motion 2", "--slow-motion: error:"},
           Case{"run " + kMinimal + " --orbit 10deg/s", "--orbit: error: this shapes"},
           Case{"run " + kMinimal + " --title Friction", "--title: error: this shapes"},
           Case{"run " + kMinimal + " --captions /nonexistent/captions.yaml",
                "--captions: error: this shapes"},
           Case{"run " + kMinimal + " --accuracy 0.01% --set world.time_step=1ms",
                "--accuracy 0.01%: error: this picks the time step, so --set world.time_step=1ms "
                "would be ignored"},
           Case{"accuracy " + kMinimal + " --duration 2s", "give --periods N instead"},
           Case{"accuracy " + kMinimal + " --set world.time_step=1ms",
                "for each point of its grid"},
           Case{"analytic --mu-k 0.3 --period-err 0.01s", "--period-err is the uncertainty"},
           Case{"analytic --mu-k 0.3 --temperature 77K", "--temperature picks the row"},
           Case{"estimate " + kMinimal + " --baud 9600", "--baud is the serial port's rate"},
       }) {
    const test::CommandResult r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args << "\n" << r.out;
  }
}

// --captions, --orbit and --title with a mistake: status 2 and a message that says where, before
// the run (no summary printed, the still's folder not made for a bad captions file).
TEST(CliRun, BadCaptionsOrbitOrTitleAreRefusedBeforeTheRun) {
  const auto dir = test_dir() / "frame-options";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string captions = (dir / "captions.yaml").string();
  std::ofstream(captions) << "captions:\n"
                             "  - {at: 2 s, text: The rollers turn toward each other.}\n"
                             "  - {at: 1 s, text: The weight is shared.}\n";
  const std::string still = " --still " + (dir / "new" / "still.png").string();
  auto r = lab("run " + kMinimal + still + " --captions " + captions);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(captions + ":3:10: error: captions[1].at: expected a time after the "
                                  "previous caption's (2 s), found 1 s"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "new"));
  r = lab("run " + kMinimal + still + " --captions " + (dir / "missing.yaml").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("missing.yaml: error: no such file"), std::string::npos) << r.err;
  for (const auto& [args, message] :
       {std::pair{" --orbit 400deg/s", "--orbit: error: expected an orbit of at most 360 deg/s"},
        std::pair{" --orbit 10mm", "--orbit: error: expected an angular speed"},
        std::pair{" --title ''", "--title: error: expected the title card's title"}}) {
    r = lab("run " + kMinimal + still + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliRun, NoNumberWithoutASource) {
  const auto far =
      lab("run " + kMinimal + " --duration 5s --json --set sensor.position=[400mm,0mm,15mm]");
  ASSERT_EQ(far.status, 0) << far.err;
  const nlohmann::json j = nlohmann::json::parse(far.out);
  for (const char* key : {"period_s", "period_std_s", "period_std_error_s", "mu_k_estimator",
                          "mu_k_err_worst", "mu_k_err_quadrature"})
    EXPECT_TRUE(!j.contains(key) || j.at(key).is_null()) << key << " = " << j.value(key, nullptr);
  EXPECT_EQ(j["periods_used"], 0);
  EXPECT_EQ(j["mu_k_source"], "trajectory: the rig's estimator accepted no period");
  EXPECT_NEAR(j["mu_k_recovered"].get<double>(), 0.29, 0.01);
  EXPECT_NE(j["period_withheld"].get<std::string>().find("the Hall sensor saw no pulse"),
            std::string::npos);
  const auto ok = nlohmann::json::parse(lab("run " + kMinimal + " --duration 5s --json").out);
  EXPECT_FALSE(ok.contains("mu_k_source"));  // from the rig's estimator, as the paper's rig
  const auto bare = nlohmann::json::parse(
      lab("run " + std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme/mu-1.yaml --json")
          .out);
  EXPECT_TRUE(bare["periods_used"].is_null());
  EXPECT_EQ(bare["mu_k_source"], "trajectory: the scene has no sensor");
}

// Ctrl-C (SIGINT) or SIGTERM during a long run: it stops after its step, writes what it did
// (marked interrupted_at_s), prints its summary and exits 130 or 143.
TEST(CliRun, AnInterruptedRunKeepsAndMarksWhatItDid) {
  for (const auto& [signal, status] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const std::filesystem::path out = test_dir() / signal;
    std::filesystem::remove_all(out);
    const auto r = test::run_command("(" + kExe + " run " + kMinimal + " --duration 5000s --out " +
                                     out.string() + " & pid=$!; sleep 1; kill -" + signal +
                                     " $pid; wait $pid; echo status $?)");
    EXPECT_NE(r.out.find("status " + std::to_string(status)), std::string::npos) << r.out << r.err;
    EXPECT_NE(r.out.find("INTERRUPTED            at t = "), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("frictionlab run: interrupted at t = "), std::string::npos) << r.err;
    std::ifstream in(out / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("interrupted_at_s"));
    const double at = j["interrupted_at_s"].get<double>();
    EXPECT_GT(at, 1.0);
    EXPECT_LT(at, 5000.0);
    EXPECT_DOUBLE_EQ(j["duration_s"].get<double>(), at);
  }
  std::filesystem::remove_all(test_dir());
}

// A run that a guard stops exits with 3 and keeps every step up to the stop: rollers turning
// outward push the plate off (no restoring force), and the outputs say when and why, with the
// trajectory ending where the plate's centre has passed a roller.
TEST(CliRun, AGuardStoppedRunExitsWithThreeAndKeepsItsOutputs) {
  const std::filesystem::path out = test_dir();
  std::filesystem::remove_all(out);
  const std::string scene =
      std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/extreme/rollers-outward.yaml";
  const auto r = lab("run " + scene + " --duration 1s --json --out " + out.string());
  EXPECT_EQ(r.status, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["failure"].is_string()) << r.out;
  EXPECT_NE(j["failure"].get<std::string>().find("left the rollers"), std::string::npos);
  const double stopped = j["duration_s"].get<double>();
  EXPECT_GT(stopped, 0.0);
  EXPECT_LT(stopped, 1.0);
  std::ifstream in(out / "summary.json");
  const nlohmann::json kept = nlohmann::json::parse(in);
  EXPECT_EQ(kept["failure"], j["failure"]);
  EXPECT_DOUBLE_EQ(kept["duration_s"].get<double>(), stopped);
  // The trajectory holds the steps up to the stop: its last row is within a step of it, with the
  // centre of mass beyond a roller's axis (|x| > l/2).
  std::ifstream trajectory(out / "trajectory.csv");
  std::string line, last;
  while (std::getline(trajectory, line))
    if (!line.empty()) last = line;
  const double t = std::stod(last.substr(0, last.find(',')));
  const std::string rest = last.substr(last.find(',') + 1);
  const double x = std::stod(rest.substr(0, rest.find(',')));
  EXPECT_NEAR(t, stopped, j["time_step_s"].get<double>() * 1.001) << last;
  EXPECT_GT(std::abs(x), 0.5 * j["spacing_m"].get<double>()) << last;
  std::filesystem::remove_all(out);
}

TEST(CliAccuracy, WritesTheStudyAndFitsTheLaw) {
  const auto out = test_dir() / "accuracy";
  const auto r = lab("accuracy " + kMinimal + " --periods 4 --json --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // The semi-implicit Euler step's phase error: -(omega dt)^2 / 24 (docs/physics.md).
  EXPECT_NEAR(j["law"]["exponent"].get<double>(), 2.0, 0.05);
  EXPECT_NEAR(j["law"]["coefficient"].get<double>() * 24.0, 1.0, 0.05);
  EXPECT_TRUE(std::filesystem::exists(out / "accuracy.csv"));
  std::filesystem::remove_all(test_dir());
}

// The physics opens no mesh: the minimal scene runs with an asset folder holding only the
// paper's table; the whole paper rig (frame, blocks, gears) with only the table and the part
// index, no mesh file at all.
TEST(CliRun, ScenesOpenNoMeshFile) {
  const auto assets = test_dir() / "assets-without-meshes";
  std::filesystem::remove_all(assets);
  std::filesystem::create_directories(assets / "paper");
  std::filesystem::copy_file(std::string(FRICTIONLAB_TEST_ASSET_DIR) + "/paper/table1.yaml",
                             assets / "paper" / "table1.yaml");
  const std::string rig = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/paper-rig.yaml";
  auto r = lab("run " + kMinimal + " --duration 2s --assets " + assets.string());
  EXPECT_EQ(r.status, 0) << r.err;
  r = lab("run " + rig + " --duration 2s --assets " + assets.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("parts.yaml"), std::string::npos) << r.err;
  std::filesystem::create_directories(assets / "lego");
  std::filesystem::copy_file(std::string(FRICTIONLAB_TEST_ASSET_DIR) + "/lego/parts.yaml",
                             assets / "lego" / "parts.yaml");
  r = lab("run " + rig + " --duration 2s --assets " + assets.string());
  EXPECT_EQ(r.status, 0) << r.err;
  std::filesystem::remove_all(assets);
}

}  // namespace
}  // namespace fl
