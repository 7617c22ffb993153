// frictionlab estimate with several logs: one row per log in one table, each log's rig from its
// sidecar or the command line, a log that gives no period a row with its error while the others go
// on (exit status 3), and the table written as a measurements file that compare --measured reads.
// The logs are synthetic Hall signals with known periods.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"
#include "core/analytic_model.hpp"
#include "estimator/synthetic_hall.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;
const std::string kExe = FRICTIONLAB_EXE;

class EstimateMany : public test::TempFolderTest {
 protected:
  EstimateMany() : TempFolderTest("fl-estimate-many") {}
  void SetUp() override {
    TempFolderTest::SetUp();
    std::filesystem::create_directories(dir_ / "logs");
  }

  // A log of a synthetic signal with period `period` (the firmware's t_us,adc format).
  std::string write_log(const std::string& name, double period, std::uint64_t seed) {
    test::HallSignal s;
    s.period_s = period;
    s.duration_s = 20.0;
    s.noise_counts = 1.5;
    s.seed = seed;
    const test::HallSamples samples = test::generate(s);
    std::string text = "t_us,adc\n";
    char line[64];
    for (std::size_t i = 0; i < samples.adc.size(); ++i) {
      std::snprintf(line, sizeof line, "%u,%u\n", samples.t_us[i], samples.adc[i]);
      text += line;
    }
    return write(name, text);
  }

  test::CommandResult lab(const std::string& args) {
    return test::run_command(kExe + " estimate " + args);
  }
};

TEST_F(EstimateMany, OneRowPerLogWithEachLogsOwnSpacingFromItsSidecar) {
  // Three logs of known periods at three spacings (from sidecars), one without a sidecar that
  // takes the command line's spacing.
  const double periods[] = {0.70, 0.79, 0.86, 0.75};
  const double spacings_mm[] = {70.0, 89.0, 105.0, 80.0};
  for (int i = 0; i < 4; ++i) {
    const std::string stem = "logs/run-" + std::to_string(i);
    write_log(stem + ".csv", periods[i], 10 + i);
    if (i < 3)
      write(stem + ".yaml", "label: spacing " + std::to_string(static_cast<int>(spacings_mm[i])) +
                                "\nspacing: " + std::to_string(spacings_mm[i]) +
                                " mm\nspacing_err: 0.5 mm\nmaterial: lego\n");
  }
  const auto r = lab((dir_ / "logs").string() + " --spacing 80mm --temperature 77K --json --out " +
                     (dir_ / "table").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out)["logs"];
  ASSERT_EQ(rows.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const nlohmann::json& row = rows[i];
    SCOPED_TRACE(row.dump());
    EXPECT_EQ(row["status"], "ok");
    // The synthetic period within 0.05 % (the estimator's claim on a clean signal).
    EXPECT_NEAR(row["period_s"].get<double>() / periods[i], 1.0, 5e-4);
    EXPECT_NEAR(row["spacing_m"].get<double>(), spacings_mm[i] * 1e-3, 1e-12);
    // mu_k from the row's own spacing: the paper's formula at that l (single precision, as the
    // rig's Arduino computes it).
    EXPECT_NEAR(row["mu_k"].get<double>() /
                    mu_k_from_period_thin(row["period_s"].get<double>(), spacings_mm[i] * 1e-3),
                1.0, 1e-5);
    // A standard error from the spread: sd / sqrt(N).
    EXPECT_NEAR(row["period_err_s"].get<double>(),
                row["period_std_s"].get<double>() / std::sqrt(row["periods_used"].get<double>()),
                1e-6);
    EXPECT_EQ(row["temperature_k"], 77.0);  // the command line's, no sidecar names one
  }
  EXPECT_EQ(rows[0]["label"], "spacing 70");
  EXPECT_EQ(rows[0]["material"], "lego");
  EXPECT_EQ(rows[3]["label"], "run-3.csv");
  EXPECT_TRUE(rows[3]["material"].is_null());
  EXPECT_TRUE(rows[3]["sidecar"].is_null());
  EXPECT_TRUE(fs::exists(dir_ / "table" / "estimates.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "table" / "estimates.json"));
}

TEST_F(EstimateMany, ALogWithoutAPeriodIsARowWithItsErrorAndTheOthersGoOn) {
  write_log("logs/a.csv", 0.79, 1);
  write("logs/b.csv", "t_us,adc\n0,512\n1000,512\n2000,513\n3000,512\n");  // no pulse at all
  write_log("logs/c.csv", 0.70, 2);
  const auto r = lab((dir_ / "logs" / "*.csv").string() + " --json");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("1 of 3 logs gave no period"), std::string::npos) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out)["logs"];
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["status"], "ok");
  EXPECT_EQ(rows[1]["status"], "failed");
  EXPECT_TRUE(rows[1]["period_s"].is_null());
  EXPECT_TRUE(rows[1]["mu_k"].is_null());
  // The error names the log and its line, as the one-log estimate does.
  EXPECT_NE(rows[1]["error"].get<std::string>().find("b.csv:"), std::string::npos) << rows[1];
  EXPECT_EQ(rows[2]["status"], "ok");
}

TEST_F(EstimateMany, ABadSidecarIsLocatedInItsRow) {
  write_log("logs/a.csv", 0.79, 1);
  write_log("logs/b.csv", 0.79, 2);
  write("logs/b.yaml", "spacing: 89 mm\nspaceing_err: 1 mm\n");
  const auto r = lab((dir_ / "logs" / "a.csv").string() + " " + (dir_ / "logs" / "b.csv").string() +
                     " --json");
  EXPECT_EQ(r.status, 3);
  const nlohmann::json rows = nlohmann::json::parse(r.out)["logs"];
  EXPECT_EQ(rows[0]["status"], "ok");
  const std::string error = rows[1]["error"];
  EXPECT_NE(error.find("b.yaml:2:1"), std::string::npos) << error;
  EXPECT_NE(error.find("spacing_err"), std::string::npos) << error;  // the suggestion
}

// A sidecar's plain "spacing: 70" is 70 m, and "material: brasss" names no material of the
// paper's: each row says so, located, and the other logs go on; --material is checked too.
TEST_F(EstimateMany, ASidecarsSlipOfTheUnitOrTheNameIsRefusedInItsRow) {
  write_log("logs/a.csv", 0.79, 1);
  write_log("logs/b.csv", 0.79, 2);
  write_log("logs/c.csv", 0.79, 3);
  write("logs/b.yaml", "spacing: 70\n");
  write("logs/c.yaml", "material: brasss\n");
  const std::string logs = (dir_ / "logs" / "a.csv").string() + " " +
                           (dir_ / "logs" / "b.csv").string() + " " +
                           (dir_ / "logs" / "c.csv").string();
  const auto r = lab(logs + " --json");
  EXPECT_EQ(r.status, 3);
  const nlohmann::json rows = nlohmann::json::parse(r.out)["logs"];
  EXPECT_EQ(rows[0]["status"], "ok");
  const std::string spacing = rows[1]["error"];
  EXPECT_NE(spacing.find("b.yaml:1:10"), std::string::npos) << spacing;
  EXPECT_NE(spacing.find("found 70000 mm"), std::string::npos) << spacing;
  const std::string material = rows[2]["error"];
  EXPECT_NE(material.find("c.yaml"), std::string::npos) << material;
  EXPECT_NE(material.find("did you mean 'brass'?"), std::string::npos) << material;
  const auto option = lab(logs + " --material brasss");
  EXPECT_EQ(option.status, 2);
  EXPECT_NE(option.err.find("--material brasss: error: unknown material"), std::string::npos)
      << option.err;
}

TEST_F(EstimateMany, OptionsThatGoWithOneLogOrTheTableAreRefusedWhereTheyDoNothing) {
  const std::string a = write_log("logs/a.csv", 0.79, 1);
  const std::string b = write_log("logs/b.csv", 0.79, 2);
  auto r = lab(a + " " + b + " --plot " + (dir_ / "x.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--plot draws one log's signal"), std::string::npos) << r.err;
  r = lab(a + " --out " + (dir_ / "t").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--out writes the table of several logs"), std::string::npos) << r.err;
  r = lab(a + " --temperature 77K");  // a temperature without the material it is of
  EXPECT_EQ(r.status, 2);
  r = lab(a + " " + b + " --duration 5s");
  EXPECT_EQ(r.status, 2);
  r = lab((dir_ / "logs" / "*.txt").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("expected the pattern to match a log"), std::string::npos) << r.err;
}

// The table is a measurements file: compare --measured reads it, each row's rig at the row's own
// spacing (rollers.spacing) with the row's thin mu_k as the reported one, and refits mu_k.
TEST_F(EstimateMany, TheTableFeedsCompareMeasured) {
  write_log("logs/a.csv", 0.80, 1);
  write("logs/a.yaml", "spacing: 89 mm\n");
  write_log("logs/b.csv", 0.50, 2);
  write("logs/b.yaml", "spacing: 45 mm\n");
  auto r = lab((dir_ / "logs").string() + " --out " + (dir_ / "table").string());
  ASSERT_EQ(r.status, 0) << r.err;
  r = test::run_command(kExe + " compare --scene " + FRICTIONLAB_TEST_SOURCE_DIR +
                        "/scenes/minimal.yaml --no-refit --json --measured " +
                        (dir_ / "table" / "estimates.csv").string() + " --out " +
                        (dir_ / "cmp").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[0]["spacing_m"].get<double>(), 0.089, 1e-12);
  EXPECT_NEAR(rows[1]["spacing_m"].get<double>(), 0.045, 1e-12);
  EXPECT_EQ(rows[0]["keys"]["rollers.spacing"], "0.089 m");
  EXPECT_NEAR(rows[0]["period_measured_s"].get<double>(), 0.80, 4e-4);
  EXPECT_NEAR(rows[0]["mu_k_reported"].get<double>(),
              mu_k_from_period_thin(rows[0]["period_measured_s"].get<double>(), 0.089), 1e-6);
}

// estimate --mc: mu_k by Monte Carlo beside the paper's rules. For errors this small (0.02 % in T,
// 1 % in l) mu_k is linear in them, so the draws' sd is the quadrature rule's; with 100000 draws
// the sd's own relative error is 1/sqrt(2 N) = 0.2 %, so 1 % is a 5-sigma band. Seeded: the same
// seed gives the same bits, another seed other draws.
TEST_F(EstimateMany, MonteCarloOfOneLogMatchesTheQuadratureRuleAndIsSeeded) {
  const std::string log = write_log("logs/a.csv", 0.79, 3);
  const auto run = [&](const std::string& extra) {
    const auto r = lab(log + " --spacing 89mm --spacing-err 1mm --json " + extra);
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const nlohmann::json a = run("--mc 100000");
  const nlohmann::json& mc = a["monte_carlo"];
  EXPECT_EQ(mc["accepted"], 100000);
  EXPECT_NEAR(mc["mu_k_sd"].get<double>() / a["mu_k_err_quadrature"].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(mc["mu_k_mean"].get<double>() / a["mu_k"].get<double>(), 1.0, 1e-3);
  EXPECT_EQ(run("--mc 100000")["monte_carlo"], mc);
  EXPECT_NE(run("--mc 100000 --seed 2")["monte_carlo"]["mu_k_mean"], mc["mu_k_mean"]);
  EXPECT_TRUE(run("")["monte_carlo"].is_null());
  // Options that would do nothing.
  EXPECT_EQ(lab(log + " --h-c-err 1mm").status, 2);
  // h_c alone gives mu_k through the thick formula, below the thin one (a thick plate
  // oscillates faster than the paper's formula assumes); one log only.
  EXPECT_TRUE(a["mu_k_thick"].is_null());
  const nlohmann::json thick = run("--h-c 3mm");
  EXPECT_LT(thick["mu_k_thick"].get<double>(), thick["mu_k"].get<double>());
  const std::string b = write_log("logs/b.csv", 0.79, 4);
  const auto two = lab(log + " " + b + " --h-c 3mm");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("--h-c gives one log's mu_k through the thick formula"), std::string::npos)
      << two.err;
  const auto many = lab(log + " " + b + " --mc 1000");
  EXPECT_EQ(many.status, 2);
  EXPECT_NE(many.err.find("give one log"), std::string::npos) << many.err;
}

// One log with a sidecar: its rig from the sidecar, as in a table, and a note that says so.
TEST_F(EstimateMany, OneLogReadsItsSidecarToo) {
  const std::string log = write_log("logs/a.csv", 0.79, 5);
  write("logs/a.yaml", "spacing: 70 mm\nspacing_err: 0.5 mm\n");
  const auto r = lab(log + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["spacing_m"].get<double>(), 0.070);
  EXPECT_DOUBLE_EQ(j["spacing_err_m"].get<double>(), 0.0005);
  EXPECT_NE(r.err.find("note: the rig from "), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fl
