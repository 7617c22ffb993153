// The web API's bodies (docs/web-api.md) from the lab's values: what the page is offered, a
// session's rig, a live frame, and the problems of a request the lab refused.
#pragma once

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "lab/live/live_run.hpp"
#include "lab/request/session_request.hpp"
#include "scene/compiled_rig.hpp"
#include "serve/board_feed.hpp"

namespace fl::serve {

// GET /api/lab: the scenes offered and the paper's Table I.
nlohmann::json lab_json(const std::vector<SceneEntry>& scenes, const PaperTable& table,
                        const std::string& version);

// A session's rig: its geometry, start, the analytic model's numbers, the paper's values.
nlohmann::json rig_json(const std::string& scene, const CompiledRig& rig,
                        const std::vector<AcceptedRange>& accepts, const PaperTable& table);

// The estimator's statistics as `state` and `rig` events carry them: null before a period was
// accepted; the spreads null with one period.
nlohmann::json estimate_json(const std::optional<EstimatorReport>& report);
// Periods as events carry them, [start, end, period, accepted], from index `from` on.
nlohmann::json periods_json(const std::vector<EstimatedPeriod>& periods, std::size_t from);

// One `state` event of the stream.
nlohmann::json frame_json(const LiveFrame& frame, bool playing, double speed);

// GET /api/rig: the serial ports a page may open (`may_choose`), and the port open or last open
// (`feed`, null before one was), or `baud` the rate one opens at.
nlohmann::json live_rig_json(const BoardFeed* feed, const std::vector<std::string>& ports,
                             bool may_choose, int baud);

// A message the lab says (text/said.hpp) as the web API's `Said`; null for none.
nlohmann::json said_json(const Said& message);
nlohmann::json said_or_null(const std::optional<Said>& message);

// A 400's body: every problem of an InputError (a RequestError's by field), spelled for the page.
nlohmann::json problems_json(const std::exception& error);

// A 404's body for a run's file it does not have (yet, or at all), saying which it keeps: a run
// longer than `most_recorded_seconds` keeps neither its steps nor its samples.
nlohmann::json missing_file_json(const std::string& name, double most_recorded_seconds);

// A 400's body for a file the lab cannot read as asked: the located message as the error, and
// one problem of the field "file", its place in the file ("log.csv:3:5") as its value.
nlohmann::json file_problem_json(const InputError& error);

// A 4xx's body for a problem of the API itself (a malformed body, an unknown session).
nlohmann::json error_json(const std::string& message);
// The same, said in the catalogues' words (its `said`), for a page to say in its language.
nlohmann::json error_json(const Said& message);

}  // namespace fl::serve
