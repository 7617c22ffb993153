// One page's session: a live run of its set-up (lab/live/live_run.hpp) on the wall clock, played,
// paused, stepped, slowed or started again by the page. Safe to call from several threads (a
// stream and the page's controls).
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "lab/live/live_run.hpp"
#include "lab/request/session_request.hpp"
#include "serve/api_requests.hpp"
#include "serve/class_table.hpp"

namespace fl::serve {

using Clock = std::chrono::steady_clock;

class LabSession {
 public:
  // `name`: who runs it, for the class's table ("" : not given).
  LabSession(std::string scene, PreparedSession prepared, std::string name = "");
  LabSession(const LabSession&) = delete;
  LabSession& operator=(const LabSession&) = delete;
  // Hands what the run recorded back to the system (malloc_trim): a class opening and closing
  // sessions all day must not grow the server (web/tests/load_bench.mjs).
  ~LabSession();

  // What a stream sends now: `state` with what changed since the last tick (the run advanced by
  // the wall time since then times the speed while playing, at most 0.1 s of simulated time a
  // tick), none when nothing did (a paused run: the time, the controls and the samples as the
  // last tick's), then, once, `done` with the run's summary. `generation` is bumped by reset.
  struct Tick {
    std::optional<nlohmann::json> state;
    std::optional<nlohmann::json> done;  // the summary, on the tick the run ended
    int generation = 0;
  };
  Tick tick(Clock::time_point now);

  // The page's controls; each answers {t, playing, speed}. Throws std::invalid_argument for an
  // action or speed it does not know.
  nlohmann::json play(Clock::time_point now);
  nlohmann::json pause();
  nlohmann::json step();
  nlohmann::json reset();
  nlohmann::json set_speed(double speed);
  // Who runs it, for the class's table ("" : not given), as the page's student types it.
  nlohmann::json set_name(std::string name);
  // The control a page's body asked for (serve/api_requests.hpp), at `now`.
  nlohmann::json control(const ControlCommand& command, Clock::time_point now);

  // The run's file by name once it has ended; nullopt before or for a file it does not keep.
  std::optional<std::string> file(const std::string& name);
  const CompiledRig& rig() const { return *prepared_.rig; }
  const std::shared_ptr<const CompiledRig>& rig_shared() const { return prepared_.rig; }
  const std::string& scene() const { return scene_; }
  std::string name() const;
  // Where its run stands, for the class's table.
  SessionStanding standing() const;
  Clock::time_point last_seen() const;
  Clock::time_point created() const { return created_; }

 private:
  nlohmann::json controls_json() const;

  const std::string scene_;
  const PreparedSession prepared_;
  std::string name_;  // under the mutex: the page may name its student later
  const Clock::time_point created_ = Clock::now();
  mutable std::mutex mutex_;
  std::unique_ptr<LiveRun> run_;
  bool playing_ = false;
  double speed_ = 1.0;
  double target_ = 0.0;  // s of simulated time the run is to reach
  std::optional<Clock::time_point> last_tick_;
  Clock::time_point last_seen_ = Clock::now();
  bool done_sent_ = false;
  // What the last state said: a tick that would say the same sends none.
  struct Said {
    double t = -1.0;
    bool playing = false;
    double speed = 0.0;
    int generation = -1;
  };
  Said said_;
  std::optional<EstimatorReport> estimate_;  // the run's estimate at the last tick
  int generation_ = 0;
};

}  // namespace fl::serve
