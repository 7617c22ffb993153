#include "hall_log/video_log.hpp"

#include "hall_log/oscillation_log.hpp"
#include "hall_log/periodic_motion.hpp"

namespace fl {

Series positions_of(const PlateTrack& track) {
  Series positions{track.t_s, track.x, {}};
  for (std::size_t k = 0; k < track.t_s.size(); ++k)
    positions.lines.push_back(static_cast<int>(k) + 1);
  return positions;
}

VideoLog read_video_log(const std::string& file, const TrackOptions& options) {
  VideoLog out;
  out.tracked = track_plate_in_video(file, options);
  const PlateTrack& track = out.tracked.track;
  const Series positions = positions_of(track);
  const Periodicity periodicity = require_periodic_motion(
      positions, SourceLocation(file), instrument_said(MeasurementFile::kVideo),
      said("column-plate-position", {arg("unit", track.unit)}));
  out.log = log_of_oscillation(positions, file, track.unit, periodicity);
  out.log.instrument = MeasurementFile::kVideo;
  out.log.channel = "x (" + track.unit + ")";
  out.log.encoding = "";  // frames, not text
  HallLogReading& r = out.log.reading;
  r.format = "video";
  r.columns_from = "tracked";
  r.time_column = "frame time";
  r.adc_column = "x (" + track.unit + ")";
  r.time_unit = "s";
  r.time_unit_from = "header";
  return out;
}

}  // namespace fl
