// POST /api/sessions answered, whatever carries the request (frictionlab serve's HTTP, the
// browser's worker): the body read, the set-up prepared and checked by the request layer, and the
// session made, or the refusal's body with every problem by field.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "serve/lab_session.hpp"

namespace fl::serve {

struct SessionOpening {
  int status = 400;     // 201 with a session; else 400
  nlohmann::json body;  // the refusal; with a session, {"rig": ...} (the caller adds id and key)
  std::shared_ptr<LabSession> session;
};

// The 400's body for a request body the API cannot take (malformed, a field of the wrong kind),
// or nothing for one it reads.
std::optional<nlohmann::json> session_body_refusal(std::string_view body);

// How long a run may be and keep its steps and Hall samples for its files (about 0.6 MB a
// simulated second) [s]: a longer one offers its summary and cycles.
inline constexpr double kMostRecordedSeconds = 120.0;

// A run longer than `most_recorded_seconds` keeps its summary and cycles and nothing step by step
// (neither trajectory.csv nor hall.csv): a session keeps about 0.6 MB a simulated second.
SessionOpening open_session(std::string_view body, const std::string& scenes_dir,
                            const std::string& asset_dir, double most_recorded_seconds);

}  // namespace fl::serve
