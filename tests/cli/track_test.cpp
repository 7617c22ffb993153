// The round trip simulate -> video -> period: the lab films the paper's rig as a phone beside it
// would (`run --camera phone --video`), and `track` and `estimate` read the plate's period back
// from the video within 0.05 % of the simulation's own (its trajectory's); the table `track`
// writes gives `estimate` the same T; what it refuses, it refuses with exit status 2 at the field.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/temp_folder.hpp"

namespace fl {
namespace {

const std::string kExe = FRICTIONLAB_EXE;
const std::string kScenes = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes";

class Track : public test::TempFolderTest {
 protected:
  Track() : TempFolderTest("fl-track") {}
  test::CommandResult lab(const std::string& args) {
    return test::run_command("cd " + dir_.string() + " && " + kExe + " " + args);
  }
};

TEST_F(Track, ThePeriodOfTheLabsOwnPhoneVideo) {
  const test::CommandResult run =
      lab("run " + kScenes +
          "/paper-rig.yaml --set world.duration=15s --camera phone --size 480x270 --video "
          "phone.mp4 --out run --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto summary = nlohmann::json::parse(run.out);
  const double truth = summary.at("period_trajectory_s").get<double>();

  const test::CommandResult track =
      lab("track phone.mp4 --out tracked --plate-length 200mm --json");
  ASSERT_EQ(track.status, 0) << track.err;
  const auto t = nlohmann::json::parse(track.out);
  EXPECT_NEAR(t.at("period_s").get<double>(), truth, 5e-4 * truth);
  EXPECT_GE(t.at("periods_used").get<int>(), 15);
  EXPECT_EQ(t.at("unit"), "mm");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "tracked" / "track.png"));

  const test::CommandResult video = lab("estimate phone.mp4 --json");
  ASSERT_EQ(video.status, 0) << video.err;
  const auto v = nlohmann::json::parse(video.out);
  EXPECT_EQ(v.at("instrument"), "video");
  EXPECT_NEAR(v.at("period_s").get<double>(), truth, 5e-4 * truth);
  // With the plate's length the amplitude is in millimetres: the run's 30 mm, within the 15 % that
  // the rig's patterned plate, guide towers and shadow leave the tracker's scale (docs/physics.md,
  // "A phone's video").
  const test::CommandResult scaled = lab("estimate phone.mp4 --plate-length 200mm --json");
  ASSERT_EQ(scaled.status, 0) << scaled.err;
  const auto s = nlohmann::json::parse(scaled.out);
  EXPECT_EQ(s.at("amplitude_unit"), "mm");
  EXPECT_NEAR(s.at("amplitude").get<double>(), 30.0, 4.5);
  // The table track wrote is a position table with the same positions: the same T.
  const test::CommandResult table = lab("estimate tracked/track.csv --json");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NEAR(nlohmann::json::parse(table.out).at("period_s").get<double>(),
              v.at("period_s").get<double>(), 1e-5);
}

TEST_F(Track, RefusalsNameTheField) {
  const test::CommandResult run =
      lab("run " + kScenes +
          "/paper-rig.yaml --set world.duration=2s --camera phone --size 320x180 --video "
          "short.mp4 --out run");
  ASSERT_EQ(run.status, 0) << run.err;
  const test::CommandResult roi = lab("track short.mp4 --out t --roi 10,20,30");
  EXPECT_EQ(roi.status, 2);
  EXPECT_NE(roi.err.find("--roi"), std::string::npos) << roi.err;
  EXPECT_NE(roi.err.find("expected the region as X,Y,W,H"), std::string::npos) << roi.err;
  const test::CommandResult outside = lab("track short.mp4 --out t --roi 300,20,100,50");
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.err.find("lies outside the video's 320x180 pixels"), std::string::npos)
      << outside.err;
  const test::CommandResult both = lab("track short.mp4 --out t --scale 0.3 --plate-length 200mm");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("expected the scale or the plate's length, found both"),
            std::string::npos)
      << both.err;
  write("notes.txt", "t,x\n");
  const test::CommandResult text = lab("track notes.txt --out t");
  EXPECT_EQ(text.status, 2);
  EXPECT_NE(text.err.find("notes.txt: error: libav cannot read it as a video"), std::string::npos)
      << text.err;
}

}  // namespace
}  // namespace fl
