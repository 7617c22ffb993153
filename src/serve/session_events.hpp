// What a session's stream sends each frame (docs/web-api.md, "The stream"), whatever carries it
// (frictionlab serve's server-sent events, the browser's worker messages): `reset` when the
// session was started again since the last frame, `state` when something changed (none while a
// paused run stays as it was), and once, at the run's end, `failed` (a run that failed) and
// `done` with the summary.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/lab_session.hpp"

namespace fl::serve {

struct SessionEvent {
  std::string name;
  nlohmann::json data;
};

// The session ticked at `now`. `generation`: the session's generation the last frame saw, which
// this updates (none before the first frame).
std::vector<SessionEvent> session_events(LabSession& session, Clock::time_point now,
                                         std::optional<int>& generation);

}  // namespace fl::serve
