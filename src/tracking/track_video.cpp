#include "tracking/track_video.hpp"

#include <optional>
#include <stdexcept>

#include "io/field_ref.hpp"
#include "io/input_error.hpp"

namespace fl {

VideoTrack track_plate_in_video(const std::string& path, const TrackOptions& options, int threads) {
  VideoTrack out;
  std::optional<PlateTracker> tracker;
  try {
    out.video = read_video_frames(
        path, kTrackedWidth,
        [&](const GrayFrame& frame, const VideoStream& stream) {
          if (!tracker) tracker.emplace(options, stream.scale);
          tracker->add(frame);
          return true;
        },
        threads);
    if (!tracker)
      throw InputError(SourceLocation(path), "expected frames in the video, found none");
    out.track = tracker->finish();
  } catch (const NoTrack& e) {
    throw InputError(SourceLocation(path), e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(SourceLocation(path), std::string(e.what()) + " (" + field_ref("roi") + ")");
  } catch (const std::domain_error& e) {
    throw InputError(SourceLocation(path),
                     std::string(e.what()) + " (" + field_ref("plate_length") + ")");
  }
  return out;
}

}  // namespace fl
