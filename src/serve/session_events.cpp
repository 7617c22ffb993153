#include "serve/session_events.hpp"

namespace fl::serve {

std::vector<SessionEvent> session_events(LabSession& session, Clock::time_point now,
                                         std::optional<int>& generation) {
  const LabSession::Tick tick = session.tick(now);
  std::vector<SessionEvent> out;
  if (generation && *generation != tick.generation)
    out.push_back({"reset", nlohmann::json::object()});
  generation = tick.generation;
  if (tick.state) out.push_back({"state", *tick.state});
  if (tick.done) {
    if (const auto failure = tick.done->find("failure");
        failure != tick.done->end() && !failure->is_null())
      out.push_back({"failed", {{"message", *failure}}});
    out.push_back({"done", *tick.done});
  }
  return out;
}

}  // namespace fl::serve
