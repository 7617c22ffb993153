// The frictionlab executable: subcommands, --json, --version, and exit status 2 with a clear
// message for bad input.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;

test::CommandResult lab(const std::string& args) {
  return test::run_command(kExe + " " + args);
}

TEST(Cli, VersionAndHelp) {
  const auto v = lab("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("frictionlab "), std::string::npos) << v.out;
  for (const char* sub : {"analytic", "table"}) {
    const auto h = lab(std::string(sub) + " --help");
    EXPECT_EQ(h.status, 0) << sub;
    EXPECT_NE(h.out.find("--json"), std::string::npos) << sub;
  }
}

TEST(Cli, AnalyticJsonForAGivenMuK) {
  const auto r = lab("analytic --spacing 89mm --mu-k 0.29 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["period_thin_s"].get<double>(), 0.7858259589972741, 1e-12);
  EXPECT_DOUBLE_EQ(j["spacing_m"].get<double>(), 0.089);
  EXPECT_TRUE(j["restoring_force"].get<bool>());
}

TEST(Cli, AnalyticForAPaperMaterialRecomputesMuK) {
  const auto r = lab("analytic --material lego --temperature 77K --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["period_measured_s"].get<double>(), 0.94);
  EXPECT_NEAR(j["mu_k_thin"].get<double>(), 0.20267259729725648, 1e-12);
  EXPECT_DOUBLE_EQ(j["mu_k_paper"].get<double>(), 0.20);
}

TEST(Cli, AnalyticReportsNoRestoringForceInsteadOfAPeriod) {
  const auto r = lab("analytic --mu-k 10 --h-c 5mm --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["restoring_force"].get<bool>());
  EXPECT_TRUE(j["period_thick_s"].is_null());
}

TEST(Cli, TableJsonHasEveryRow) {
  const auto r = lab("table --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rows"].size(), 15u);
  EXPECT_EQ(j["rows_disagreeing"].get<int>(), 4);
}

TEST(Cli, BadInputExitsWithStatusTwoAndSaysWhy) {
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c : {
           Case{"analytic --mu-k 0.3 --spacing 89kg", "--spacing: error: expected a length"},
           // SI: 89 is 89 m, beyond any bench: refused, saying how it was read.
           Case{"analytic --mu-k 0.3 --spacing 89",
                "--spacing 89: error: expected the roller spacing l from 1 to 2000 mm (the "
                "paper's rig: 89 mm), found 89000 mm: a plain number is SI, so 89 was read as "
                "89 m; write 89mm for millimetres"},
           Case{"analytic --mu-k 1e300", "expected mu_k from 0.001 to 100"},
           Case{"analytic --mu-k 0.3 --spacing 1e300m", "found 1e+303 mm"},
           Case{"analytic --period 1e-9s", "expected the period T from 0.0044857 to 63.4374 s"},
           Case{"table --h-c 1km", "--h-c 1km: error: expected the centre-of-mass height h_c"},
           Case{"analytic --mu-k -1", "mu_k must be a finite positive number"},
           Case{"analytic --period 0s", "the period T must be a finite positive number"},
           Case{"analytic --mu-k 0.3 --period 1s", "give exactly one of"},
           Case{"analytic --material unobtainium", "unknown material"},
           Case{"analytic --material iron --temperature 77K", "at 300 K only"},
           Case{"nosuchcommand",
                "\"nosuchcommand\" is not a frictionlab command; the commands: "
                "analytic, table, run"},
           Case{"rum scenes/minimal.yaml", "(did you mean 'run'?)"},
           Case{"sweeep x.yaml", "(did you mean 'sweep'?)"},
           Case{"table --assets /nonexistent", "no such file"},
       }) {
    const auto r = lab(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
  }
  // A scene's value beyond any bench, from --set: refused before the run, not computed with.
  const auto speed = lab("run " + std::string(FRICTIONLAB_TEST_SOURCE_DIR) +
                         "/scenes/minimal.yaml --set rollers.speed=1e300rpm");
  EXPECT_EQ(speed.status, 2) << speed.err;
  EXPECT_NE(speed.err.find("rollers.speed: expected the rollers' speed from 0 to 100000 rpm"),
            std::string::npos)
      << speed.err;
}

// docs/using-the-lab.md's claims on flexible foam (mu_k = 10): the minimal plate, released at
// 20 mm, beyond l/2 - mu_k h_c = 18.7 mm, tips; a plate 10 mm thick (h_c above 4.45 mm) has no
// restoring force and the loader refuses it.
TEST(Cli, FlexibleFoamTipsTheMinimalPlateAndAThickPlateIsRefused) {
  const std::string minimal = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
  const auto tips =
      lab("run " + minimal + " --set friction.mu_k=flexible-foam --duration 1s --json");
  ASSERT_EQ(tips.status, 0) << tips.err;
  EXPECT_EQ(nlohmann::json::parse(tips.out)["regime"], "tips");
  const auto thick =
      lab("run " + minimal + " --set friction.mu_k=flexible-foam --set plate.thickness=10mm");
  EXPECT_EQ(thick.status, 2);
  EXPECT_NE(thick.err.find("no oscillation exists: l = 89 mm <= 2 mu_k h_c"), std::string::npos)
      << thick.err;
}

TEST(Cli, AnUnknownMaterialIsAnsweredWithTheTablesMaterials) {
  const auto r = lab("analytic --material plexiglass");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(
      r.err.find(
          "--material plexiglass: error: unknown material \"plexiglass\"; the paper's materials "
          "are "
          "lego, paper, "),
      std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("did you mean 'plexiglas'?"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fl
