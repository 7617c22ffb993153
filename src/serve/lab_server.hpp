// `frictionlab serve`'s server (docs/web-api.md): the page's files, the LEGO parts, and the API
// that starts sessions, streams their runs as server-sent events and takes the page's controls.
// cpp-httplib (Debian's libcpp-httplib-dev) underneath; every request is answered, bad input with
// a 4xx and a JSON body naming the problem, and the server goes on serving the others.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "hall_log/serial_port.hpp"
#include "serve/board_feed.hpp"
#include "serve/session_opening.hpp"

namespace fl::serve {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;         // 0: any free port (bind() says which)
  std::string scenes_dir;  // the scenes offered, by name
  std::string web_dir;     // the built page (index.html, app.js, ...)
  std::string asset_dir;   // the lab's data (the paper's table, the LEGO parts)
  std::string version;     // what /api/lab reports
  // A session nobody streams from or controls for this long [s] ends (looked at with each API
  // request).
  double idle_seconds = 600.0;
  // The class's table lists a session while its page is seen (streaming, or a request within
  // this long [s]): a closed tab's session leaves the table then, though it stays open for
  // idle_seconds in case the page comes back.
  double listed_seconds = 20.0;
  // Sessions open at once; a page beyond them is refused, saying so (503). Each session costs
  // about 1 % of a core at real time (bench_serve): 30 leave the 2-core machine room.
  int max_sessions = 30;
  // A shared secret: when set, every /api/ request carries it (?token=, or the header
  // X-Frictionlab-Token), else 403. The page and the parts are served without it.
  std::string token;
  // A session keeps its run's steps and Hall samples for its files (about 0.6 MB a simulated
  // second) only for runs up to this long [s]; a longer one offers its summary and cycles.
  double most_recorded_seconds = kMostRecordedSeconds;
  // API requests a client (by address) may make a second, on average; three times as many at
  // once. A stream counts once, when it opens.
  double requests_per_second = 20.0;
  // The live rig (docs/web-api.md): a serial port read from the start ("" : none), its baud
  // rate, and a folder the rig's raw log is written into as it comes ("" : kept in memory only).
  std::string serial_port;
  int serial_baud = kFirmwareBaud;
  std::string record_dir;
  // Whether a page may open a serial port itself (one the server lists): on a server for this
  // machine only. Set by the server from `host` unless given.
  std::optional<bool> pages_choose_port;
  // The most bytes of the rig's raw log kept (and read) before its port is closed.
  std::size_t most_rig_log_bytes = kMostRigLogBytes;
  // The serial devices' folder (/dev; another for a test).
  std::string device_dir = "/dev";
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
  // Ends the streams (each told so by `event: closed`), closes the rig's port, its log written
  // whole, and stops serving.
  void stop();
  // Where the rig's raw log was written (--record), when a line came.
  std::optional<std::string> rig_record_path() const;
  // How many sessions are open.
  int sessions() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl::serve
