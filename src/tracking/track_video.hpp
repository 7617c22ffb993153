// A video file's plate tracked: its frames decoded as a stream (tracking/video_frames.hpp) into the
// tracker (tracking/plate_tracker.hpp). Memory holds the frames the tracker learns from (600 at
// most, scaled down to 480 pixels across: about 80 MB for any video) and the decoder's own frames
// (a few at the video's size), however long the video.
#pragma once

#include <string>

#include "tracking/plate_tracker.hpp"
#include "tracking/video_frames.hpp"

namespace fl {

// The width the tracker reads frames at [pixels]: finer than a plate's edge blurs in a phone's
// video, coarse enough that learning stays small.
inline constexpr int kTrackedWidth = 480;

struct VideoTrack {
  VideoStream video;
  PlateTrack track;
};

// Throws InputError located at `path` for a file that is no readable video, one too short, one
// where nothing moves or nothing moves together (what was found: the largest change against the
// noise, how many pixels changed), a region outside the frames (⟦roi⟧) or a plate length the
// video cannot give (⟦plate_length⟧).
VideoTrack track_plate_in_video(const std::string& path, const TrackOptions& options,
                                int threads = 0);

}  // namespace fl
