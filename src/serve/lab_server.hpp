// `frictionlab serve`'s server (docs/web-api.md): the page's files, the LEGO parts, and the API
// that starts sessions, streams their runs as server-sent events and takes the page's controls.
// cpp-httplib (Debian's libcpp-httplib-dev) underneath; every request is answered, bad input with
// a 4xx and a JSON body naming the problem, and the server goes on serving the others.
#pragma once

#include <memory>
#include <string>

namespace fl::serve {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;         // 0: any free port (bind() says which)
  std::string scenes_dir;  // the scenes offered, by name
  std::string web_dir;     // the built page (index.html, app.js, ...)
  std::string asset_dir;   // the lab's data (the paper's table, the LEGO parts)
  std::string version;     // what /api/lab reports
  int idle_minutes = 10;   // a session nobody streams from or controls for this long ends
  // Sessions open at once; a page beyond them is refused, saying so (503). Each session costs
  // about 1 % of a core at real time (bench_serve): 30 leave the 2-core machine room.
  int max_sessions = 30;
  // A shared secret: when set, every /api/ request carries it (?token=, or the header
  // X-Frictionlab-Token), else 403. The page and the parts are served without it.
  std::string token;
  // A session keeps its run's steps and Hall samples for its files (about 0.6 MB a simulated
  // second) only for runs up to this long [s]; a longer one offers its summary and cycles.
  double most_recorded_seconds = 120.0;
};

class LabServer {
 public:
  explicit LabServer(ServeOptions options);
  LabServer(const LabServer&) = delete;
  LabServer& operator=(const LabServer&) = delete;
  ~LabServer();

  // Binds the host and port; returns the port (the one chosen, for port 0). Throws
  // std::runtime_error saying what failed.
  int bind();
  // Serves until stop() (from another thread or a signal's watcher).
  void listen();
  void stop();
  // How many sessions are open.
  int sessions() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl::serve
