// The plate followed in a video without clicks: the object that moves back and forth along one
// line. A phone's video of the rig shows the plate as a slab of one colour whose ends sweep over
// the background as it swings; every pixel an end passes over turns from the background's grey
// to the plate's and back. The tracker learns from the first frames (up to `learn_frames`):
//  - each pixel's two states (the medians of its grey either side of the middle of its 2nd to
//    98th percentile); a pixel whose states differ by 16 levels and 8 times the video's noise
//    may be covered and uncovered;
//  - the one motion they share: the first principal component of their coverage over time (the
//    fraction of the way from one state to the other). The plate's edges are the pixels that
//    follow it as an edge passing over them does: in one state while the motion is below some
//    value, in the other above it (a step, in either sense). Pixels that change for other reasons
//    (the rollers' turning marks, which turn at the drive's pace and not the plate's, light,
//    noise) fit no step and are left out;
//  - the line of the motion (the principal axis of the followed pixels), and how much the area
//    they cover grows for each pixel the plate moves: with the frames in order of that area, each
//    followed pixel turns at some area, and the pixel k further along the line turns k pixels of
//    motion later (the median over pairs up to 8 pixels apart).
// Then each frame's position along the line is the area covered over that growth: linear in the
// plate's displacement, to a fraction of a pixel (a pixel half covered counts half), whether
// each end has a strip of its own or a plate's pattern joins its edges into one band. The
// followed region reaches from one end's furthest swing to the other's, so its extent less the
// swing is the plate's length in pixels, and a plate length in millimetres gives the scale.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tracking/gray_frame.hpp"

namespace fl {

struct TrackOptions {
  // The region to search, in the video's pixels: x, y (its top-left corner), width, height.
  std::optional<std::array<int, 4>> roi;
  std::optional<double> mm_per_px;        // the video's scale [mm per video pixel]
  std::optional<double> plate_length_mm;  // or the plate's length, both ends in view
  int learn_frames = 600;
};

// What the tracker followed and found.
struct PlateTrack {
  std::vector<double> t_s;          // each frame's time [s]
  std::vector<double> x;            // the plate's position along the motion, from its mean over the
                                    // frames learned from; in `unit`
  std::string unit;                 // "mm" with a scale, else "px" (the video's pixels)
  std::optional<double> mm_per_px;  // the scale used; none without one
  std::string scale_from;           // "scale", "plate length" or "" (none)
  double direction_deg = 0.0;       // the motion's line in the picture: 0 across, 90 up and down
  int pixels_followed = 0;          // pixels of the frames the tracker read (scaled down)
  int edges = 0;  // separate patches of them (a plain plate's two ends: 2; a patterned one: 1)
  std::optional<double> plate_length_px;  // the followed region's extent less the swing;
                                          // none when it is not longer than the swing
  double noise_grey = 0.0;                // the video's noise [grey levels]
  int frames_learned = 0;
  std::array<int, 4> region{};  // searched, in the video's pixels
  // For the picture of what was followed: the first frame, and each of its pixels' part: 0 not
  // followed, 1 followed (the frames' own pixels, scaled down by `scale`).
  GrayFrame first;
  std::vector<std::uint8_t> followed;
  double scale = 1.0;  // the frames' pixels per video pixel
};

// Why a video gives no track: nothing moves, or nothing moves together. Its message says what
// was found.
class NoTrack : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PlateTracker {
 public:
  // `scale`: the frames' pixels per video pixel (VideoStream::scale).
  PlateTracker(TrackOptions options, double scale);
  // Takes the next frame (all of one size, in order of time).
  void add(const GrayFrame& frame);
  // The track; throws NoTrack when nothing to follow was found, std::invalid_argument for a
  // region outside the frames, std::domain_error for a plate length with one end in view.
  PlateTrack finish();

 private:
  void learn();
  void set_unit();
  double position(const GrayFrame& frame) const;

  TrackOptions options_;
  PlateTrack track_;
  std::array<int, 4> box_{};  // the region in the frames' pixels
  std::vector<GrayFrame> learning_;
  bool learned_ = false;
  // The followed pixels (indices into a frame), their two states and the sense of their change.
  std::vector<std::size_t> pixels_;
  std::vector<float> low_;
  std::vector<float> span_;
  std::vector<std::int8_t> sense_;
  double mean_cover_ = 0.0;
  double area_per_px_ = 1.0;  // the covered area's growth per pixel of motion [frame pixels]
  double unit_per_frame_px_ = 1.0;
};

}  // namespace fl
