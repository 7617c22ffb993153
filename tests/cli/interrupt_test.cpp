// Ctrl-C (SIGINT) or SIGTERM in the long commands besides run and sweep: compare, accuracy and
// stability start nothing more, finish or drop what is running, write what they finished, say so
// and exit 130 (143). Each job here is long enough (minutes on this project's 2-core machine)
// that the signal, a second after the start, comes before its end.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../support/run_command.hpp"

namespace {

const std::string kExe = FRICTIONLAB_EXE;
const std::string kSource = FRICTIONLAB_TEST_SOURCE_DIR;

std::filesystem::path test_dir() {
  return std::filesystem::temp_directory_path() /
         ("frictionlab-cli-interrupt-" + std::to_string(::getpid()));
}

long lines(const std::string& text) {
  return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// Starts `args`, sends `signal` a second later, and returns what it printed and "status N".
fl::test::CommandResult interrupted(const std::string& args, const std::string& signal = "INT") {
  return fl::test::run_command("(" + kExe + " " + args + " & pid=$!; sleep 1; kill -" + signal +
                               " $pid; wait $pid; echo status $?)");
}

TEST(Interrupt, AccuracyKeepsTheFinishedPointsAndExits130) {
  const std::filesystem::path out = test_dir() / "accuracy";
  const auto r = interrupted("accuracy " + kSource + "/scenes/minimal.yaml --periods 1000 --out " +
                             out.string());
  EXPECT_NE(r.out.find("status 130"), std::string::npos) << r.out << r.err;
  const std::string said = "frictionlab accuracy: interrupted after ";
  const auto at = r.err.find(said);
  ASSERT_NE(at, std::string::npos) << r.err;
  const long points = std::stol(r.err.substr(at + said.size()));
  // The points finished, each whole, and nothing of the one running.
  EXPECT_EQ(lines(fl::test::read_text(out / "accuracy.csv")), points + 1);
  EXPECT_LT(points, 28);
  std::filesystem::remove_all(out);
}

TEST(Interrupt, StabilityFinishesTheCasesRunningAndExits143OnSigterm) {
  // A catalogue of twenty copies of the slowest case (the Stribeck drop's bisection, about 1.4 s
  // each here): twenty cases take far longer than a second.
  const std::filesystem::path dir = test_dir() / "catalogue";
  std::filesystem::create_directories(dir);
  const std::string scene = fl::test::read_text(kSource + "/scenes/extreme/stribeck-drop.yaml");
  for (int i = 0; i < 20; ++i)
    std::ofstream(dir / ("case-" + std::to_string(i) + ".yaml")) << scene;
  const std::filesystem::path out = test_dir() / "stability";
  const auto r =
      interrupted("stability -j 1 --dir " + dir.string() + " --out " + out.string(), "TERM");
  EXPECT_NE(r.out.find("status 143"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("frictionlab stability: interrupted; kept: the "), std::string::npos)
      << r.err;
  // The case running when the signal came is finished and kept; the others are not run.
  const long kept = lines(fl::test::read_text(out / "stability.csv")) - 1;
  EXPECT_GE(kept, 1);
  EXPECT_LT(kept, 20);
  EXPECT_NE(r.err.find(std::to_string(20 - kept) + " not run"), std::string::npos) << r.err;
  std::filesystem::remove_all(test_dir());
}

TEST(Interrupt, CompareKeepsTheRowsDoneAndMarksTheRest) {
  const std::filesystem::path out = test_dir() / "compare";
  const auto r = interrupted("compare -j 1 --duration 60s --out " + out.string());
  EXPECT_NE(r.out.find("status 130"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("frictionlab compare: interrupted; kept: the "), std::string::npos) << r.err;
  // Every row of Table I is in the file, each compared or marked interrupted.
  const std::string csv = fl::test::read_text(out / "compare.csv");
  EXPECT_EQ(lines(csv), 16);
  EXPECT_NE(csv.find(",interrupted,"), std::string::npos) << csv;
  std::filesystem::remove_all(out);
}

}  // namespace
