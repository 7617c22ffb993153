// A phone's video of the rig with its plate followed, as every front end asks for it
// (`frictionlab track VIDEO --out DIR`): the plate's position along its motion at each frame,
// written as a position table that `estimate` reads (track.csv), and a picture of what was
// followed drawn on the first frame (track.png), so that a student sees that the lab followed the
// plate and not the background; with the period the rig's estimator finds in it. The request owns
// its defaults and checks (problems by field).
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "estimator/period_estimator.h"
#include "lab/request/field_checks.hpp"
#include "tracking/track_video.hpp"

namespace fl {

struct TrackRequest {
  std::string video;                          // "video": the file
  std::string out;                            // "out": the folder for track.csv and track.png
  std::string roi;                            // "roi": "X,Y,W,H" in the video's pixels; "" all
  std::optional<double> scale;                // "scale": millimetres per pixel of the video
  std::optional<QuantityInput> plate_length;  // "plate_length": or the plate's length
};

struct TrackResult {
  VideoTrack tracked;
  std::string csv;  // the files written
  std::string still;
  // The amplitude in the track's unit: the least-squares sinusoid's at its strongest frequency
  // (hall_log/periodic_motion.hpp), as estimate gives it.
  double amplitude = 0.0;
  fl_estimator::Stats stats{};  // the rig's estimator on the track (its period; no mu_k here)
  nlohmann::json json() const;  // `track --json`'s object (docs/cli.md)
};

// Checks every field (RequestError), then tracks and writes. Throws InputError located at the
// video for one that gives no track.
TrackResult track_video(const TrackRequest& request);

}  // namespace fl
