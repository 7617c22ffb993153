// Frames decoded outside the lab (the browser's page, tracking/given_video.hpp) served through the
// decoder module's seam: the tracker reading them gives the track it gives for the same frames
// handed to it directly; the stream says what the page said of the video; a video given no
// frames, one the page could not decode and frames wider than asked are refused, saying which.
#include "tracking/given_video.hpp"

#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/synthetic_plate_video.hpp"
#include "tracking/plate_tracker.hpp"

namespace fl {
namespace {

struct Reading {
  int status = 0;
  std::string error;
  DecodedVideoInfo info{};
  PlateTracker* tracker = nullptr;
  int frames = 0;
};

Reading read(const std::string& path, int most_width, PlateTracker* tracker = nullptr) {
  Reading out;
  out.tracker = tracker;
  char error[512] = {};
  const auto hand_on = [](void* user, const DecodedGreyFrame* frame,
                          const DecodedVideoInfo*) -> int {
    auto* r = static_cast<Reading*>(user);
    ++r->frames;
    if (r->tracker != nullptr) {
      GrayFrame grey;
      grey.width = frame->width;
      grey.height = frame->height;
      grey.t_s = frame->t_s;
      grey.levels.assign(frame->levels, frame->levels + frame->width * frame->height);
      r->tracker->add(grey);
    }
    return 1;
  };
  out.status = given_video_decoder()->read(path.c_str(), most_width, 1, hand_on, &out, &out.info,
                                           error, sizeof error);
  out.error = error;
  return out;
}

class GivenVideoTest : public ::testing::Test {
 protected:
  void TearDown() override { forget_given_videos(); }
};

TEST_F(GivenVideoTest, TheTrackerReadsTheGivenFramesAsItReadsThemDirectly) {
  const test::PlateScene scene;
  std::mt19937 random(scene.seed);
  GivenVideo video;
  video.container = "mp4";
  video.codec = "avc1.64001e";
  video.width = 480;
  video.height = 270;
  video.fps = 30.0;
  video.scale = 0.5;
  for (int k = 0; k < 300; ++k) video.frames.push_back(scene.frame(k / 30.0, random));

  TrackOptions options;
  options.learn_frames = 240;
  PlateTracker direct(options, 0.5);
  for (const GrayFrame& frame : video.frames) direct.add(frame);
  const PlateTrack expected = direct.finish();

  give_video("plate.mp4", video);
  PlateTracker through(options, 0.5);
  // The file is found by its name wherever it was written.
  const Reading r = read("/tmp/upload-x1/plate.mp4", 480, &through);
  ASSERT_EQ(r.status, 0) << r.error;
  EXPECT_EQ(r.frames, 300);
  EXPECT_EQ(r.info.frames_read, 300);
  EXPECT_STREQ(r.info.container, "mp4");
  EXPECT_STREQ(r.info.codec, "avc1.64001e");
  EXPECT_EQ(r.info.width, 480);
  EXPECT_EQ(r.info.scale, 0.5);
  const PlateTrack track = through.finish();
  EXPECT_EQ(track.t_s, expected.t_s);
  EXPECT_EQ(track.x, expected.x);
}

TEST_F(GivenVideoTest, AVideoWithoutFramesOrUndecodedOrTooWideIsRefused) {
  EXPECT_NE(read("phone.mp4", 480).error.find("without its frames"), std::string::npos);
  GivenVideo failed;
  failed.failure = "this browser cannot decode HEVC (hvc1): record in H.264";
  give_video("iphone.mov", failed);
  const Reading r = read("iphone.mov", 480);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.error, failed.failure);

  GivenVideo wide;
  std::mt19937 random(1);
  wide.frames.push_back(test::PlateScene{}.frame(0.0, random));
  give_video("wide.mp4", wide);
  EXPECT_NE(read("wide.mp4", 100).error.find("240 pixels across"), std::string::npos);
}

TEST_F(GivenVideoTest, FramesOfAnotherSizeOrOutOfOrderAreRefusedWhenGiven) {
  std::mt19937 random(3);
  GivenVideo video;
  video.frames.push_back(test::PlateScene{}.frame(0.0, random));
  video.frames.push_back(test::PlateScene{}.frame(0.0, random));
  EXPECT_THROW(give_video("same-time.mp4", video), std::invalid_argument);
  video.frames.back().t_s = 1.0 / 30;
  test::PlateScene small;
  small.width = 120;
  video.frames.push_back(small.frame(2.0 / 30, random));
  EXPECT_THROW(give_video("two-sizes.mp4", video), std::invalid_argument);
}

}  // namespace
}  // namespace fl
