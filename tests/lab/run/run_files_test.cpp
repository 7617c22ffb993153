// A run's files streamed as the run goes (lab/run/run_files.hpp) are byte for byte the files made
// from a run kept in memory: for the minimal scene (every file), and for a run that starts again
// at more solver iterations (what came before the restart is forgotten). The run keeps none of
// its steps or samples in memory while it streams them. The phones' files likewise.
#include "lab/run/run_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include "lab/run/run_outputs.hpp"
#include "support/close_rollers.hpp"
#include "support/scene_fixture.hpp"
#include "support/temp_folder.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

class RunFilesTest : public test::TempFolderTest {
 protected:
  RunFilesTest() : TempFolderTest("frictionlab-run-files") {}

  // Runs `scene` both ways into dir/streamed and dir/kept; the streamed run's summary.
  RunSummary run_both(const Scene& scene) {
    const CompiledRig rig = compile_rig(scene);
    const std::string streamed = (dir_ / "streamed").string();
    RunFiles files(streamed, scene.output, rig);
    RunRecording small;
    const RunSummary summary = run_experiment(rig, files.options(), &small);
    EXPECT_TRUE(small.trajectory.empty());
    EXPECT_TRUE(small.hall.empty());
    files.finish(summary, small);

    RunRecording kept;
    const RunSummary again = run_experiment(rig, recording_for(scene.output), &kept);
    EXPECT_FALSE(kept.trajectory.empty());
    write_run_outputs((dir_ / "kept").string(), scene.output, rig, again, kept);
    return summary;
  }

  void expect_same_files() {
    std::size_t compared = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_ / "kept")) {
      const std::string name = e.path().filename().string();
      if (name == "timing.json") continue;  // the run's cost differs
      EXPECT_EQ(test::read_text(dir_ / "streamed" / name), test::read_text(e.path())) << name;
      ++compared;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "streamed"), {}),
              std::distance(fs::directory_iterator(dir_ / "kept"), {}));
    EXPECT_GE(compared, 2u);
  }
};

TEST_F(RunFilesTest, EveryFileOfTheMinimalSceneIsTheRecordingsFile) {
  Scene scene =
      test::scene_file("minimal.yaml", std::vector<SceneOverride>{{"world.duration", "5 s"}});
  scene.output.cycles = true;
  // Two phones beside the rig and one on the plate, each its own file.
  PhoneDesc beside;
  beside.position = {0.12, 0.06, -0.01};
  const PhoneDesc on_plate = phone_with(PhoneSensor::kAccelerometer);  // 400 Hz
  scene.phones = {beside, on_plate, beside};
  scene.phones[2].position[1] = -0.06;
  run_both(scene);
  expect_same_files();
  for (const char* name :
       {"trajectory.csv", "hall.csv", "periods.csv", "cycles.csv", "summary.json",
        "phone-magnetometer.csv", "phone-accelerometer.csv", "phone-magnetometer-2.csv"})
    EXPECT_TRUE(fs::exists(dir_ / "streamed" / name)) << name;
  // 5 s at 400 Hz: a header and 2001 samples (t = 0 and every 2.5 ms to 5 s).
  const std::string phone = test::read_text(dir_ / "streamed" / "phone-accelerometer.csv");
  EXPECT_EQ(std::count(phone.begin(), phone.end(), '\n'), 2002);
}

TEST_F(RunFilesTest, ARunThatStartsAgainStreamsOnlyTheRunItEndsWith) {
  Scene scene = test::stuck_on_close_rollers();
  scene.output.trajectory = true;
  const PhoneDesc phone = phone_with(PhoneSensor::kAccelerometer);
  scene.phones = {phone};
  const RunSummary summary = run_both(scene);
  ASSERT_TRUE(summary.solver_iterations_raised.has_value());
  expect_same_files();
  // The phone's file holds the run it ended with: its samples once, from t = 0.
  const std::string samples = test::read_text(dir_ / "streamed" / "phone-accelerometer.csv");
  EXPECT_EQ(static_cast<double>(std::count(samples.begin(), samples.end(), '\n')),
            std::floor(summary.duration * phone.rate + 1e-9) + 2.0);
  // One header, and one row per step of the run it ended with.
  const std::string trajectory = test::read_text(dir_ / "streamed" / "trajectory.csv");
  EXPECT_EQ(static_cast<long long>(std::count(trajectory.begin(), trajectory.end(), '\n')),
            summary.steps + 2);
}

}  // namespace
}  // namespace fl
