// A phone's video of the rig read as a log: the plate tracked without clicks
// (tracking/track_video.hpp), its position along the motion timed as a position table's is
// (hall_log/oscillation_log.hpp: a virtual sensor at the upper end of the swing), each frame a
// sample whose "line" is its frame number.
#pragma once

#include <string>

#include "hall_log/hall_log.hpp"
#include "hall_log/measurement_table.hpp"
#include "tracking/track_video.hpp"

namespace fl {

// The log, and the track it was read from (for what the command shows of it). Throws InputError
// located at the file, as track_plate_in_video does.
struct VideoLog {
  HallLog log;
  VideoTrack tracked;
};
VideoLog read_video_log(const std::string& file, const TrackOptions& options);

// A track's positions as a table's are read: each frame a sample, its "line" its frame number.
Series positions_of(const PlateTrack& track);

}  // namespace fl
