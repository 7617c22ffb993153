// frictionlab fit SERIES.csv and the --mc option of fit and analytic, run as a student runs them:
// series written from the thick-plate closed form with a known mu_k and h_c come back through the
// command; bad series exit with 2 and a message located at the cell at fault; the Monte Carlo is
// reproducible from its seed and matches the quadrature rule for small errors.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_folder.hpp"
#include "core/analytic_model.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;
constexpr double kMuK = 0.29;
constexpr double kHc = 0.0036;

class Fit : public test::TempFolderTest {
 protected:
  Fit() : TempFolderTest("fl-fit") {}

  // Periods from the closed form at 60 to 120 mm, written with 17 digits in seconds, spacings
  // in millimetres.
  std::string exact_series(const std::string& name = "series.csv") {
    std::string text = "label,spacing,period,period_err\n";
    for (int l_mm = 60; l_mm <= 120; l_mm += 10)
      text += fmt::format("at {} mm,{} mm,{:.17g} s,5 ms\n", l_mm, l_mm,
                          period_thick(l_mm * 1e-3, kMuK, kHc, kDefaultGravity));
    return write(name, text);
  }

  test::CommandResult lab(const std::string& args) { return test::run_command(kExe + " " + args); }

  nlohmann::json json(const std::string& args) {
    const test::CommandResult r = lab(args + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

TEST_F(Fit, AnExactSeriesGivesBackItsMuKAndHc) {
  const nlohmann::json j = json("fit " + exact_series());
  // Text in, text out: 17 digits each way; the fit itself keeps ~1e-14 (core test).
  EXPECT_NEAR(j["mu_k"].get<double>(), kMuK, 1e-12);
  EXPECT_NEAR(j["h_c_m"].get<double>(), kHc, 1e-13);
  EXPECT_LT(j["chi2"].get<double>(), 1e-18);
  EXPECT_EQ(j["degrees_of_freedom"], 5);
  EXPECT_EQ(j["rows"].size(), 7u);
  EXPECT_EQ(j["rows"][0]["label"], "at 60 mm");
  EXPECT_EQ(j["rows"][0]["line"], 2);
  EXPECT_TRUE(j["rows"][0]["spacing_err_m"].is_null());  // not given: null, not 0
  EXPECT_NEAR(j["rows"][0]["mu_k_thin"].get<double>(),
              mu_k_from_period_thin(period_thick(0.060, kMuK, kHc), 0.060), 1e-12);
  EXPECT_TRUE(j["monte_carlo"].is_null());
  EXPECT_TRUE(j["through_rig"].is_null());
  EXPECT_TRUE(j["plot"].is_null());
}

TEST_F(Fit, TwoRowsHaveNoChiSquaredPerDegreeOfFreedom) {
  const std::string file =
      write("two.csv", fmt::format("spacing,period,period_err\n70mm,{:.17g},2ms\n"
                                   "110mm,{:.17g},2ms\n",
                                   period_thick(0.070, kMuK, kHc), period_thick(0.110, kMuK, kHc)));
  const nlohmann::json j = json("fit " + file);
  EXPECT_EQ(j["degrees_of_freedom"], 0);
  EXPECT_TRUE(j["chi2_per_dof"].is_null());
  EXPECT_NEAR(j["mu_k"].get<double>(), kMuK, 1e-12);
}

TEST_F(Fit, OutWritesCsvAndJsonAndPlotDrawsThePng) {
  const std::string out = (dir_ / "out").string();
  const test::CommandResult r = lab("fit " + exact_series() + " --out " + out + " --plot");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("written: " + out + "/fit.csv, " + out + "/fit.json, " + out + "/fit.png"),
            std::string::npos)
      << r.out;
  const nlohmann::json j = nlohmann::json::parse(test::read_text(out + "/fit.json"));
  EXPECT_NEAR(j["mu_k"].get<double>(), kMuK, 1e-12);
  const std::string csv = test::read_text(out + "/fit.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "line,label,spacing_m,spacing_err_m,period_s,period_err_s,period_squared_err_s2,"
            "period_fit_s,residual_sigma,mu_k_thin");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 8);
  std::ifstream png(out + "/fit.png", std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  // --plot without a file and without --out has nowhere to draw.
  const test::CommandResult none = lab("fit " + exact_series() + " --plot");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--plot: error: expected a PNG to draw"), std::string::npos) << none.err;
}

TEST_F(Fit, BadSeriesExitWithTwoAndTheCellAtFault) {
  struct Case {
    const char* text;
    const char* message;
  };
  for (const Case& c : {
           Case{"spacing,period,period_err\n89 mm,0.79 s,5 ms\n",
                "bad.csv:2: error: expected at least 2 rows"},
           Case{"spacing,period,period_err\n89 mm,0.79 s,5 ms\n89 mm,0.80 s,5 ms\n"
                "89mm,0.81 s,5 ms\n",
                "bad.csv:4:1: error: expected at least two different spacings, found every row "
                "at 89 mm"},
           Case{"spacing,period,period_err\n89 mm,0.79 s,5 ms\n100 mm,-0.8 s,5 ms\n",
                "bad.csv:3:8: error: period: expected the period T greater than 0, found "
                "\"-0.8 s\""},
           Case{"spacing,period\n89 mm,0.79 s\n100 mm,0.8 s\n",
                "bad.csv:1:1: error: expected a header naming spacing, period and period_err, "
                "found no period_err column"},
           Case{"spacing,period,period_err,temperature\n",
                "bad.csv:1:27: error: expected a column named spacing, period, period_err, "
                "spacing_err (optional), label (optional), found \"temperature\""},
           // T^2 falling as l grows: no positive mu_k.
           Case{"spacing,period,period_err\n70 mm,0.9 s,5 ms\n110 mm,0.8 s,5 ms\n",
                "bad.csv: error: expected T^2 to grow with the spacing"},
           // Two tight rows whose steep line reaches T^2 = 0 at 82 mm, above the first row's
           // spacing: no restoring force there, whatever that row says.
           Case{"spacing,period,period_err\n30 mm,0.3 s,50 ms\n89 mm,0.5 s,1 ms\n"
                "100 mm,0.79 s,1 ms\n",
                "bad.csv:2:1: error: the fitted line leaves no restoring force at this spacing"},
       }) {
    const std::string file = write("bad.csv", c.text);
    const test::CommandResult r = lab("fit " + file);
    EXPECT_EQ(r.status, 2) << c.text << r.err;
    EXPECT_NE(r.err.find(file.substr(0, file.size() - 7) + c.message), std::string::npos)
        << "expected: " << c.message << "\nfound: " << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
  const test::CommandResult missing = lab("fit " + (dir_ / "none.csv").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.csv: error: cannot open the spacing series"), std::string::npos)
      << missing.err;
}

// The paper's value for the plate's material beside the fitted mu_k (LEGO at 77 K: mu_k 0.20 +-
// 0.01): the difference in combined standard errors computed here from the two values and their
// errors; none without a material; a material or temperature the paper lacks refused.
TEST_F(Fit, TheFittedMuKBesideThePapersValueForItsMaterial) {
  const std::string series = exact_series();
  const nlohmann::json j = json("fit " + series + " --material lego --temperature 77K");
  const nlohmann::json& paper = j["paper"];
  EXPECT_EQ(paper["material"], "LEGO blocks");
  EXPECT_EQ(paper["temperature_k"], 77.0);
  EXPECT_EQ(paper["mu_k"], 0.20);
  const double mu = j["mu_k"], err = j["mu_k_err"];
  EXPECT_NEAR(paper["difference_standard_errors"].get<double>(),
              (mu - 0.20) / std::sqrt(err * err + 0.01 * 0.01), 1e-9);
  const test::CommandResult text = lab("fit " + series + " --material lego");
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("LEGO blocks at 300 K: mu_k 0.29 +- 0.03"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("the fitted mu_k is +0.0 combined standard errors from it (they agree)"),
            std::string::npos)
      << text.out;
  EXPECT_TRUE(json("fit " + series)["paper"].is_null());
  struct Case {
    const char* options;
    const char* message;
  };
  for (const Case& c : {Case{" --material legoo", "--material legoo: error: unknown material"},
                        Case{" --temperature 77K",
                             "--temperature: error: --temperature goes with "
                             "--material"},
                        Case{" --material iron --temperature 77K",
                             "--temperature: error: the paper measured Iron at 300 K only"}}) {
    const test::CommandResult r = lab("fit " + series + c.options);
    EXPECT_EQ(r.status, 2) << c.options;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

TEST_F(Fit, MonteCarloIsReproducibleFromItsSeedAndBesideTheFitsErrors) {
  const std::string file = exact_series();
  const test::CommandResult a = lab("fit " + file + " --mc 4000 --json");
  const test::CommandResult b = lab("fit " + file + " --mc 4000 --seed 1 --json");
  const test::CommandResult c = lab("fit " + file + " --mc 4000 --seed 2 --json");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);  // the default seed is 1, and the same seed gives the same bytes
  EXPECT_NE(a.out, c.out);
  const nlohmann::json j = nlohmann::json::parse(a.out);
  const nlohmann::json& mc = j["monte_carlo"];
  EXPECT_EQ(mc["draws"], 4000);
  EXPECT_EQ(mc["seed"], 1);
  EXPECT_EQ(mc["accepted"].get<int>() + mc["skipped"].get<int>(), 4000);
  // 4000 draws: a sample sd within 4 / sqrt(2 N) = 4.5 % of the fit's standard error.
  const double tol = 4.0 / std::sqrt(2.0 * 3999);
  EXPECT_NEAR(mc["mu_k"]["sd"].get<double>() / j["mu_k_err"].get<double>(), 1.0, tol);
  EXPECT_NEAR(mc["h_c_m"]["sd"].get<double>() / j["h_c_err_m"].get<double>(), 1.0, tol);
  EXPECT_LT(mc["mu_k"]["quantile_025"].get<double>(), kMuK);
  EXPECT_GT(mc["mu_k"]["quantile_975"].get<double>(), kMuK);
  EXPECT_NEAR(mc["correlation"].get<double>(), j["correlation"].get<double>(), 0.02);
}

TEST_F(Fit, MonteCarloCountsOfZeroOrLessOrNotANumberAreRefused) {
  const std::string file = exact_series();
  for (const char* n : {"0", "-5", "abc", "1e3", "20000000"}) {
    for (const std::string& command :
         {"fit " + file, std::string("analytic --period 0.79s --period-err 0.02s")}) {
      const test::CommandResult r = lab(command + " --mc " + n);
      EXPECT_EQ(r.status, 2) << command << " --mc " << n;
      EXPECT_NE(r.err.find("--mc " + std::string(n) +
                           ": error: expected the number of draws, a whole number from 1 to "
                           "10000000"),
                std::string::npos)
          << r.err;
    }
  }
  const test::CommandResult seed = lab("fit " + file + " --seed 3");
  EXPECT_EQ(seed.status, 2);
  EXPECT_NE(seed.err.find("--seed requires --mc"), std::string::npos) << seed.err;
}

TEST_F(Fit, ThroughTheRigReportsEverySimulation) {
  // Three spacings of the minimal scene's plate at its own h_c: the rig agrees with the closed
  // form to ~1e-4 (docs/physics.md), so mu_k moves by less than its error.
  std::string text = "spacing,period,period_err\n";
  for (const double l : {0.075, 0.089, 0.105})
    text += fmt::format("{:.17g},{:.17g},1ms\n", l, period_thick(l, kMuK, 0.0025792));
  const nlohmann::json j = json("fit " + write("rig.csv", text) + " --through-rig");
  const nlohmann::json& rig = j["through_rig"];
  ASSERT_FALSE(rig.is_null());
  EXPECT_EQ(rig["scene"], "minimal");
  EXPECT_NEAR(rig["h_c_scene_m"].get<double>(), 0.0025792, 1e-7);
  EXPECT_EQ(rig["simulations"].get<int>(), 3 * rig["iterations"].get<int>());
  EXPECT_TRUE(rig["converged"].get<bool>());
  EXPECT_LT(std::fabs(rig["mu_k"].get<double>() - kMuK), rig["mu_k_err"].get<double>());
  for (const nlohmann::json& row : j["rows"]) {
    EXPECT_EQ(row["period_simulated_source"], "hall estimator");
    EXPECT_NEAR(row["correction"].get<double>(), 1.0, 1e-4);
  }
  const test::CommandResult no_rig = lab("fit " + write("r2.csv", text) + " --scene x.yaml");
  EXPECT_EQ(no_rig.status, 2);
  EXPECT_NE(no_rig.err.find("add --through-rig"), std::string::npos) << no_rig.err;
}

TEST(AnalyticMonteCarlo, SmallErrorsGiveTheQuadratureRuleAndTheSeedItsBytes) {
  const std::string args =
      "analytic --period 0.79s --period-err 0.79ms --spacing 89mm --spacing-err 0.089mm --mc "
      "200000 --json";
  const test::CommandResult a = test::run_command(kExe + " " + args);
  const test::CommandResult b = test::run_command(kExe + " " + args + " --seed 1");
  const test::CommandResult c = test::run_command(kExe + " " + args + " --seed 99");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
  const nlohmann::json j = nlohmann::json::parse(a.out);
  const nlohmann::json& mc = j["monte_carlo"];
  // 0.1 % errors: linearisation is exact to ~1e-6; the sd of 200 000 draws is within
  // 4 / sqrt(2 N) = 0.63 % of the true one.
  EXPECT_NEAR(mc["mu_k_sd"].get<double>() / j["mu_k_thick_err_quadrature"].get<double>(), 1.0,
              4.0 / std::sqrt(2.0 * 199999));
  EXPECT_EQ(mc["skipped"], 0);
  EXPECT_LT(mc["mu_k_quantile_025"].get<double>(), mc["mu_k_mean"].get<double>());
  EXPECT_GT(mc["mu_k_quantile_975"].get<double>(), mc["mu_k_mean"].get<double>());
}

TEST(AnalyticMonteCarlo, TextReportAndHistogramAndRefusals) {
  const std::string png =
      (std::filesystem::temp_directory_path() / ("fl-mc-" + std::to_string(::getpid()) + ".png"))
          .string();
  const test::CommandResult r = test::run_command(
      kExe + " analytic --material lego --h-c 3.6mm --h-c-err 0.5mm --mc 20000 --plot " + png);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("mu_k, Monte Carlo"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(mean and sd of 20000 draws, seed 1); 95 % in ["), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("the rules above leave dh_c out"), std::string::npos) << r.out;
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
  std::filesystem::remove(png);
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c : {
           Case{"analytic --mu-k 0.29 --mc 1000", "--mc: error: carries a measured period's"},
           Case{"analytic --period 0.79s --plot x.png", "--plot: error: draws the Monte Carlo's"},
           Case{"analytic --period 0.79s --mc 100 --h-c-err -1mm", "--h-c-err: error: expected"},
       }) {
    const test::CommandResult bad = test::run_command(kExe + " " + c.args);
    EXPECT_EQ(bad.status, 2) << c.args;
    EXPECT_NE(bad.err.find(c.message), std::string::npos) << c.args << ": " << bad.err;
  }
}

}  // namespace
}  // namespace fl
