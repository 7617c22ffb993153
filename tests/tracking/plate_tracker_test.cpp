// The tracker against frames drawn with a known motion (support/synthetic_plate_video.hpp): it
// follows the plate's two ends to a fraction of a pixel and leaves the roller's turning mark out,
// finds the line of a motion that is not level, takes millimetres from the plate's length, and
// refuses a still picture and a flickering one with what it found.
#include "tracking/plate_tracker.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/synthetic_plate_video.hpp"

namespace fl {
namespace {

using test::PlateScene;

PlateTrack tracked(const PlateScene& scene, double seconds, double fps, TrackOptions options = {}) {
  options.learn_frames = 240;
  PlateTracker tracker(options, 1.0);
  std::mt19937 random(scene.seed);
  for (int k = 0; k < static_cast<int>(seconds * fps); ++k)
    tracker.add(scene.frame(k / fps, random));
  return tracker.finish();
}

// The least-squares line x = slope d + offset through the track against the truth, and the
// scatter about it.
struct Fit {
  double slope = 0.0;
  double rms = 0.0;
};
Fit fit_to_truth(const PlateTrack& track, const PlateScene& scene) {
  const auto n = static_cast<double>(track.t_s.size());
  double md = 0.0, mx = 0.0;
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    md += scene.displacement(track.t_s[k]) / n;
    mx += track.x[k] / n;
  }
  double sdd = 0.0, sdx = 0.0;
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    const double d = scene.displacement(track.t_s[k]) - md;
    sdd += d * d;
    sdx += d * (track.x[k] - mx);
  }
  Fit fit;
  fit.slope = sdx / sdd;
  double sum = 0.0;
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    const double r = track.x[k] - mx - fit.slope * (scene.displacement(track.t_s[k]) - md);
    sum += r * r;
  }
  fit.rms = std::sqrt(sum / n);
  return fit;
}

TEST(PlateTracker, FollowsBothEndsToAFractionOfAPixel) {
  const PlateScene scene;
  const PlateTrack track = tracked(scene, 12.0, 30.0);
  ASSERT_EQ(track.t_s.size(), 360u);  // the frames learned from, then the rest as they came
  const Fit fit = fit_to_truth(track, scene);
  // The 2nd and 98th percentiles bound each pixel's states: the last 0.2 % of the swing's ends
  // is not seen, which no slope reaches 2 % from.
  EXPECT_NEAR(fit.slope, 1.0, 0.02);
  EXPECT_LT(fit.rms, 0.25) << "px";
  EXPECT_EQ(track.unit, "px");
  EXPECT_FALSE(track.mm_per_px.has_value());
  EXPECT_NEAR(track.direction_deg, 0.0, 0.5);
  EXPECT_EQ(track.edges, 2);
  ASSERT_TRUE(track.plate_length_px.has_value());
  EXPECT_NEAR(*track.plate_length_px, scene.plate_length_px, 1.0);
  // The roller's mark changes more than the plate's ends do, at its own pace: not followed.
  for (int y = 80; y < 94; ++y)
    for (int x = 112; x < 128; ++x)
      EXPECT_EQ(track.followed[static_cast<std::size_t>(y) * scene.width + x], 0) << x << "," << y;
}

TEST(PlateTracker, MillimetresFromThePlatesLength) {
  const PlateScene scene;
  TrackOptions options;
  options.plate_length_mm = 200.0;
  const PlateTrack track = tracked(scene, 10.0, 30.0, options);
  ASSERT_TRUE(track.mm_per_px.has_value());
  EXPECT_NEAR(*track.mm_per_px, 200.0 / scene.plate_length_px,
              0.01 * 200.0 / scene.plate_length_px);
  EXPECT_EQ(track.unit, "mm");
  EXPECT_EQ(track.scale_from, "plate length");
  EXPECT_NEAR(fit_to_truth(track, scene).slope, 200.0 / scene.plate_length_px,
              0.03 * 200.0 / 120.0);
}

TEST(PlateTracker, TheLineOfAMotionThatIsNotLevel) {
  PlateScene scene;
  scene.direction_deg = 30.0;
  scene.samples = 3;
  scene.width = 200;
  scene.height = 150;
  scene.centre_x = 100.0;
  scene.centre_y = 75.0;
  scene.plate_length_px = 90.0;
  scene.roller_hz = 0.0;
  const PlateTrack track = tracked(scene, 9.0, 30.0);
  EXPECT_NEAR(track.direction_deg, 30.0, 3.0);
  // Along the line, up and to the right, is positive.
  EXPECT_GT(fit_to_truth(track, scene).slope, 0.9);
  EXPECT_LT(fit_to_truth(track, scene).slope, 1.1);
}

TEST(PlateTracker, ARegionLeavesTheOtherEndOut) {
  const PlateScene scene;
  TrackOptions options;
  options.roi = std::array<int, 4>{150, 40, 80, 40};  // the right end only
  const PlateTrack track = tracked(scene, 10.0, 30.0, options);
  EXPECT_EQ(track.edges, 1);
  EXPECT_FALSE(track.plate_length_px.has_value());
  EXPECT_NEAR(fit_to_truth(track, scene).slope, 1.0, 0.03);
  options.plate_length_mm = 200.0;
  EXPECT_THROW(tracked(scene, 10.0, 30.0, options), std::domain_error);
  options.plate_length_mm.reset();
  options.roi = std::array<int, 4>{200, 40, 80, 40};  // beyond the right side
  EXPECT_THROW(tracked(scene, 10.0, 30.0, options), std::invalid_argument);
}

TEST(PlateTracker, AStillPictureIsRefusedWithItsNoise) {
  PlateScene scene;
  scene.amplitude_px = 0.0;
  scene.roller_hz = 0.0;
  try {
    tracked(scene, 10.0, 30.0);
    FAIL() << "a still picture gave a track";
  } catch (const NoTrack& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("nothing moves in the video"), std::string::npos) << what;
    EXPECT_NE(what.find("240 frames (8.0 s)"), std::string::npos) << what;
  }
}

TEST(PlateTracker, FlickerIsNoMotion) {
  // Every pixel black or white at random in every frame: all change, none together.
  PlateTracker tracker(TrackOptions{}, 1.0);
  std::mt19937 random(5);
  std::bernoulli_distribution white(0.5);
  for (int k = 0; k < 300; ++k) {
    GrayFrame f;
    f.width = 64;
    f.height = 48;
    f.t_s = k / 30.0;
    for (int p = 0; p < f.width * f.height; ++p) f.levels.push_back(white(random) ? 255 : 0);
    tracker.add(f);
  }
  try {
    tracker.finish();
    FAIL() << "flicker gave a track";
  } catch (const NoTrack& e) {
    EXPECT_NE(std::string(e.what()).find("nothing moves back and forth"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fl
