// frictionlab serve: the lab in a browser. Prints the page's address and serves it until Ctrl-C
// or SIGTERM (the server is serve/lab_server.hpp; its API docs/web-api.md).
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/stop_signals.hpp"
#include "hall_log/serial_port.hpp"
#include "io/input_error.hpp"
#include "lab/request/lab_data.hpp"

#if FRICTIONLAB_WITH_SERVE
#include <malloc.h>

#include "serve/lab_server.hpp"
#endif

namespace fl::cli {
namespace {

struct ServeCommandOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string scenes = FRICTIONLAB_DEFAULT_SCENES_DIR;
  std::string web;
  int max_sessions = 30;
  std::string token;
  std::string serial;
  double baud = kFirmwareBaud;
  std::string record;
  double rate = 20.0;
};

#if FRICTIONLAB_WITH_SERVE
// The built page: beside the executable (web/), where the build puts it.
std::string default_web_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("web") : (exe.parent_path() / "web").string();
}
#endif

int run_serve(const ServeCommandOptions& o, const GlobalOptions& global) {
#if FRICTIONLAB_WITH_SERVE
  std::error_code ec;
  if (!std::filesystem::is_directory(o.scenes, ec))
    throw InputError(SourceLocation{o.scenes},
                     "expected a folder of scenes (*.yaml), found none there; give --scenes DIR");
  serve::ServeOptions options;
  options.host = o.host;
  options.port = o.port;
  options.scenes_dir = o.scenes;
  options.web_dir = o.web.empty() ? default_web_dir() : o.web;
  options.asset_dir = asset_dir(global.asset_dir);
  options.version = std::string("frictionlab ") + FRICTIONLAB_VERSION;
  options.max_sessions = o.max_sessions;
  options.token = o.token;
  if (const std::optional<std::string> why = baud_problem(o.baud))
    throw InputError(SourceLocation::of_field("baud", fmt::format("{:g}", o.baud)), *why);
  options.requests_per_second = o.rate;
  options.serial_port = o.serial;
  options.serial_baud = static_cast<int>(o.baud);
  if (!o.record.empty()) {
    std::filesystem::create_directories(o.record, ec);
    if (ec || !std::filesystem::is_directory(o.record))
      throw InputError(SourceLocation::of_field("record", o.record),
                       "expected a folder the rig's log can be written into, and could not make "
                       "one there" +
                           (ec ? ": " + ec.message() : std::string()) + "; give another --record");
    options.record_dir = o.record;
  }
  if (!std::filesystem::exists(std::filesystem::path(options.web_dir) / "index.html", ec))
    throw InputError(SourceLocation{options.web_dir},
                     "expected the built page (index.html), found none: build it (cmake --build "
                     "--preset release builds web/ when Node.js and npm are installed) or give "
                     "--web DIR");
  // Each stream runs on its own thread, and glibc gives threads their own malloc arenas, which
  // keep what a closed session freed: opening and closing sessions for a minute grew the
  // resident size 6-fold. Two arenas return it (web/tests/load_bench.mjs; bench/README.md's table).
  mallopt(M_ARENA_MAX, 2);
  serve::LabServer server(options);
  int port = 0;
  try {
    port = server.bind();
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation::of_field("port", std::to_string(o.port)), e.what());
  }
  const std::string shown = o.host == "0.0.0.0" ? "127.0.0.1" : o.host;
  fmt::print("frictionlab serve: the lab at http://{}:{}/{} (Ctrl-C ends it)\n", shown, port,
             o.token.empty() ? "" : "?token=" + o.token);
  fmt::print("  the class's table at http://{}:{}/class.html{}\n", shown, port,
             o.token.empty() ? "" : "?token=" + o.token);
  if (!o.serial.empty())
    fmt::print("  the live rig from {} at {:.0f} baud{}\n", o.serial, o.baud,
               o.record.empty() ? "" : ", its log written into " + o.record);
  std::fflush(stdout);
  StopSignals signals;
  std::thread watcher([&server] {
    while (!stop_requested().load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    server.stop();
  });
  server.listen();
  // listen() returns on stop(), or when the server failed; the watcher ends with the signal.
  if (!stop_requested().load()) {
    watcher.detach();
    fmt::print(stderr, "frictionlab serve: the server stopped\n");
    return 1;
  }
  watcher.join();
  fmt::print("frictionlab serve: stopped ({} session{} open)\n", server.sessions(),
             server.sessions() == 1 ? "" : "s");
  if (const auto log = server.rig_record_path()) fmt::print("  the rig's log: {}\n", *log);
  return 0;
#else
  (void)o;
  (void)global;
  throw InputError(SourceLocation{},
                   "this build has no server: install libcpp-httplib-dev and build again");
#endif
}

}  // namespace

Command add_serve_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<ServeCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "serve", "The lab in a browser: serves the page and its live simulations; prints the URL");
  sub->add_option("--port", options->port, "Port to listen on (0: any free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  sub->add_option("--host", options->host,
                  "Address to listen on (0.0.0.0 shares it with the network)")
      ->capture_default_str();
  sub->add_option("--scenes", options->scenes, "Folder of the scenes the page offers, by name")
      ->capture_default_str();
  sub->add_option("--max-sessions", options->max_sessions,
                  "Sessions open at once; a page beyond them is told the lab is full")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  sub->add_option("--token", options->token,
                  "A shared secret the page's address carries (?token=...); the API answers "
                  "only to it")
      ->check([](const std::string& t) {
        for (const char c : t)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
            return std::string("expected letters, digits, '-' and '_' only (it goes in a URL)");
        return t.empty() ? std::string("expected a token, found none") : std::string();
      });
  sub->add_option("--serial", options->serial,
                  "The rig's serial port (/dev/ttyACM0): its Hall signal and periods live in "
                  "every page, beside the simulation");
  sub->add_option("--baud", options->baud, "With --serial: the port's baud rate (the firmware's)")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 4e6));
  sub->add_option("--record", options->record,
                  "Folder the rig's raw log is written into, line by line as it comes");
  sub->add_option("--rate", options->rate,
                  "API requests a second each client may make (three times as many at once)")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 10000.0));
  sub->add_option("--web", options->web,
                  "Folder of the built page (default: web/ beside the executable)");
  return {sub, [options, &global] { return run_serve(*options, global); }};
}

}  // namespace fl::cli
