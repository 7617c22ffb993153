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
  // DELETE /api/sessions/ID.
  Answer end(const std::string& id);
  // POST /api/estimate?name=&spacing=&h_c=: the file's bytes read by the lab's readers.
  Answer estimate(const std::string& name, std::string bytes, std::optional<std::string> spacing,
                  std::optional<std::string> h_c) const;

 private:
  struct Open {
    std::shared_ptr<serve::LabSession> session;
    std::optional<int> generation;  // the last frame's
  };
  Open* find(const std::string& id);

  std::string scenes_dir_;
  std::string asset_dir_;
  std::string version_;
  std::map<std::string, Open> sessions_;
  unsigned next_id_ = 1;
};

}  // namespace fl::browser
