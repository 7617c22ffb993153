// What the lab's server answers, recorded for the page's tests to play back without the lab
// (web/tests/mock_server.mjs): the offer (`GET /api/lab`), each set-up's session or refusal, its
// run's `state` events at the server's frame interval with the class's row at each, its summary;
// and a board for the live rig: the Hall lines of a simulated run and what the rig's estimator
// judges in them, for each spacing a session may have. Every body is made by the functions the
// server answers with (serve/api_json.hpp, LabSession, BoardWatch's reading), so the mock holds no
// physics and no table of its own.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/request/session_request.hpp"

namespace fl::serve {

struct ApiRecordingRequest {
  // The scenes offered, as scene files: each is served from its own folder, by name.
  std::vector<std::string> scene_files;
  std::string asset_dir;
  std::string version;  // `GET /api/lab`'s
  // A `world.duration=...` entry added to a set-up that names none (the page's tests want short
  // runs); "" : none added.
  std::string duration_entry;
  std::vector<SessionRequest> setups;
  // The run whose Hall samples the fake board sends, one scene of scene_files with its entries.
  SessionRequest board;
};

// {"declaration", "lab", "frame_interval_s", "setups": [{"scene", "set", "status", "body",
// "frames": [{"state", "row"}], "summary"}], "board": {"header", "baud", "shown_s", "t_us": [...],
// "adc": [...], "readings": [{"spacing", "changes": [{"samples", "periods", "estimate",
// "geometry"}]}]}}; see web/tests/mock_server.mjs for how it is played.
nlohmann::json record_api(const ApiRecordingRequest& request);

}  // namespace fl::serve
