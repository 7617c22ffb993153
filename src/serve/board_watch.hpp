// A page's view of the live rig (serve/board_feed.hpp): the board's samples run through the rig's
// estimator with the page's own spacing, and what the next `rig` event carries
// (docs/web-api.md): the samples, periods and state since the last one.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "lab/logs/live_log_estimate.hpp"
#include "scene/compiled_rig.hpp"
#include "serve/board_feed.hpp"

namespace fl::serve {

class BoardWatch {
 public:
  // The samples an event carries at most, the last of them: the page's plot of the rig.
  static constexpr double kShownSeconds = 10.0;  // s

  // l, dl, g and the pulses per period the estimate is made with.
  explicit BoardWatch(const LogSetUp& set_up);
  // A session's: its rig's spacing and gravity, the pulses per period found in the signal.
  static LogSetUp set_up_for(const CompiledRig& rig);

  // The next `rig` event of `feed`, or nothing when nothing changed since the last. A feed other
  // than the last one watched (a port opened again) starts the view again, as does the board
  // restarting; `run` counts these starts, so the page knows to clear its plots.
  std::optional<nlohmann::json> next(const std::shared_ptr<const BoardFeed>& feed);

 private:
  LogSetUp set_up_;
  std::shared_ptr<const BoardFeed> feed_;
  int feed_run_ = -1;  // the board's run the estimate is on
  int run_ = -1;       // the runs shown so far, less one
  std::size_t next_sample_ = 0;
  std::unique_ptr<LiveLogEstimate> live_;
  std::size_t periods_sent_ = 0;
  std::string status_sent_;  // the last event's state, message and lines
};

// What a `rig` event says of the rig's estimator now: {"estimate", "geometry"}.
nlohmann::json board_reading_json(const LiveLogEstimate& live);

}  // namespace fl::serve
