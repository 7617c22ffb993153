// Videos written through libav (H.264 in MP4, as a phone writes them) of a plate with a known
// period (support/synthetic_plate_video.hpp), read back as a log: the period within 0.05 % at a
// phone's 30 and 60 frames a second, with noise and a shaking camera; a file cut short, a file
// that is no video and a video where nothing moves refused, located at the file.
#include "tracking/track_video.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/log_estimate.hpp"
#include "support/filmed_plate.hpp"
#include "support/temp_folder.hpp"
#include "tracking/video_decoder_module.hpp"

namespace fl {
namespace {

// The decoder module the build made (looked for beside the executable otherwise).
const bool kDecoderNamed = [] {
  setenv(kVideoDecoderVariable, FRICTIONLAB_TEST_DECODER_MODULE, 0);
  return true;
}();

using test::PlateScene;

class TrackVideo : public test::TempFolderTest {
 protected:
  TrackVideo() : TempFolderTest("fl-track-video") {}

  // The scene filmed for `seconds` at `fps`, written as an MP4; its path.
  std::string film(const PlateScene& scene, double seconds, int fps, const std::string& name) {
    const std::string path = (dir_ / name).string();
    test::film_plate(scene, seconds, fps, path);
    return path;
  }
};

PlateScene phone_scene() {
  PlateScene scene;
  scene.width = 320;
  scene.height = 180;
  scene.centre_x = 160.0;
  scene.centre_y = 88.0;
  scene.plate_length_px = 160.0;
  scene.amplitude_px = 25.0;
  return scene;
}

TEST_F(TrackVideo, ThePeriodOfAPhonesVideo) {
  const PlateScene scene = phone_scene();
  const std::string path = film(scene, 20.0, 30, "phone.mp4");
  const HallLog log = read_hall_log(path);
  EXPECT_EQ(log.instrument, MeasurementFile::kVideo);
  EXPECT_EQ(log.reading.format, "video");
  EXPECT_EQ(log.t_s.size(), 600u);
  const LogEstimate e = estimate_log(log, LogSetUp{}, false);
  EXPECT_GE(e.stats.periods_used, 20u);
  EXPECT_NEAR(e.stats.period_s, scene.period_s, 5e-4 * scene.period_s);

  const VideoTrack t = track_plate_in_video(path, TrackOptions{});
  EXPECT_EQ(t.video.width, 320);
  EXPECT_EQ(t.video.codec, "h264");
  EXPECT_NEAR(t.video.fps, 30.0, 1e-9);
  EXPECT_EQ(t.track.edges, 2);
  EXPECT_NEAR(*t.track.plate_length_px, scene.plate_length_px, 1.5);
}

TEST_F(TrackVideo, SixtyFramesASecondWithAShakingCamera) {
  PlateScene scene = phone_scene();
  scene.shake_px = 0.5;
  scene.noise_grey = 3.0;
  const std::string path = film(scene, 30.0, 60, "shaking.mp4");
  const LogEstimate e = estimate_log(read_hall_log(path), LogSetUp{}, false);
  EXPECT_GE(e.stats.periods_used, 30u);
  EXPECT_NEAR(e.stats.period_s, scene.period_s, 5e-4 * scene.period_s);
}

TEST_F(TrackVideo, AVideoCutShortIsRefused) {
  const std::string path = film(phone_scene(), 3.0, 30, "cut.mp4");
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size * 6 / 10);
  try {
    track_plate_in_video(path, TrackOptions{});
    FAIL() << "a video cut short was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    const std::string what = e.what();
    EXPECT_TRUE(what.find("cut short") != std::string::npos ||
                what.find("damaged") != std::string::npos)
        << what;
  }
}

TEST_F(TrackVideo, AFileThatIsNoVideoIsRefused) {
  const std::string path = write("notes.mp4", "t,x\n0,1\n");
  try {
    track_plate_in_video(path, TrackOptions{});
    FAIL() << "text was read as a video";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("libav cannot read it as a video"), std::string::npos)
        << e.what();
  }
}

TEST_F(TrackVideo, AVideoWhereNothingMovesIsRefused) {
  PlateScene scene = phone_scene();
  scene.amplitude_px = 0.0;
  scene.roller_hz = 0.0;
  const std::string path = film(scene, 2.0, 30, "still.mp4");
  try {
    read_hall_log(path);
    FAIL() << "a still video gave a log";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_NE(std::string(e.what()).find("nothing moves in the video"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fl
