// The lab in the page's Web Worker (tools/site): the web API's requests (docs/web-api.md)
// answered without a server, by the same request layer, sessions, bodies and readers as
// frictionlab serve (serve/), on the worker's in-memory files: the scenes and assets the site
// carries, and the measurement files the student chooses. One page is its only client, so a
// session needs no key and the lab no limits of a shared server's.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "serve/board_feed.hpp"
#include "serve/board_watch.hpp"
#include "serve/lab_session.hpp"

namespace fl::browser {

// A request's answer: the status the server would send and its JSON body.
struct Answer {
  int status = 200;
  nlohmann::json body;
};

class BrowserLab {
 public:
  // `scenes_dir`, `asset_dir`: where the worker's files hold the scenes offered and the lab's
  // data; `version`: what GET /api/lab says the lab is.
  BrowserLab(std::string scenes_dir, std::string asset_dir, std::string version);

  // GET /api/lab.
  Answer lab() const;
  // POST /api/sessions: 201 {"id", "key": "", "rig"}, or 400 with the problems.
  Answer create_session(std::string_view body);
  // A frame of GET /api/sessions/ID/stream: [{"event": NAME, "data": ...}, ...] at the wall
  // clock's now.
  Answer events(const std::string& id);
  // POST /api/sessions/ID/control.
  Answer control(const std::string& id, std::string_view body);
  // GET /api/sessions/ID/files/NAME: 200 {"text": the file}, or 404.
  Answer file(const std::string& id, const std::string& name);
  // POST /api/sessions/ID/report: 200 {"html": the report}, or the error.
  Answer report(const std::string& id, std::string_view body);
  // DELETE /api/sessions/ID.
  Answer end(const std::string& id);
  // POST /api/estimate?name=&spacing=&h_c=: the file's bytes read by the lab's readers.
  Answer estimate(const std::string& name, std::string bytes, std::optional<std::string> spacing,
                  std::optional<std::string> h_c) const;

  // The live rig, its port read by the page (Web Serial) and its bytes given here: what
  // GET /api/rig says (no ports listed: the browser lists them), a port opened under `port`'s
  // name at `baud` (the one open before closed, a new log begun), the bytes that came (`ended`:
  // the port went away after them), the port closed. Each answers GET /api/rig's body. The
  // sessions' streams carry its `rig` events, each with the session's spacing.
  Answer rig() const;
  Answer rig_open(const std::string& port, int baud);
  Answer rig_bytes(std::string_view bytes, bool ended);
  Answer rig_close();
  // GET /api/rig/log: {"name", "text"}: every line as received; 404 before a line came.
  Answer rig_log() const;

 private:
  struct Open {
    std::shared_ptr<serve::LabSession> session;
    std::optional<int> generation;  // the last frame's
    serve::BoardWatch rig_watch;    // the live rig with the session's spacing
  };
  Open* find(const std::string& id);

  std::string scenes_dir_;
  std::string asset_dir_;
  std::string version_;
  std::map<std::string, Open> sessions_;
  std::shared_ptr<serve::BoardFeed> rig_;  // the port open or last open
  unsigned next_id_ = 1;
};

}  // namespace fl::browser
