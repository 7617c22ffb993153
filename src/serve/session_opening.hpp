// POST /api/sessions answered, whatever carries the request (frictionlab serve's HTTP, the
// browser's worker), once its body is read (serve/api_requests.hpp): the set-up prepared and
// checked by the request layer, and the session made, or the refusal's body with every problem
// by field.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "serve/api_requests.hpp"
#include "serve/lab_session.hpp"

namespace fl::serve {

struct SessionOpening {
  std::shared_ptr<LabSession> session;  // none: the set-up was refused (400)
  nlohmann::json body;  // the refusal; with a session, {"rig": ...} (the caller adds id and key)
};

// How long a run may be and keep its steps and Hall samples for its files (about 0.6 MB a
// simulated second) [s]: a longer one offers its summary and cycles.
inline constexpr double kMostRecordedSeconds = 120.0;

// A run longer than `most_recorded_seconds` keeps its summary and cycles and nothing step by step
// (neither trajectory.csv nor hall.csv): a session keeps about 0.6 MB a simulated second.
SessionOpening open_session(const SessionBody& asked, const std::string& scenes_dir,
                            const std::string& asset_dir, double most_recorded_seconds);

}  // namespace fl::serve
