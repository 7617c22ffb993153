#include "serve/lab_server.hpp"

#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <httplib.h>

#include "hall_log/serial_ports.hpp"
#include "io/input_error.hpp"
#include "lab/request/lab_data.hpp"
#include "serve/api_json.hpp"
#include "serve/api_requests.hpp"
#include "serve/board_feed.hpp"
#include "serve/board_watch.hpp"
#include "serve/bounded_server.hpp"
#include "serve/class_table.hpp"
#include "serve/lab_session.hpp"
#include "serve/measurement_upload.hpp"
#include "serve/path_scrubber.hpp"
#include "serve/rate_limit.hpp"
#include "serve/session_events.hpp"
#include "serve/session_key.hpp"
#include "serve/session_opening.hpp"
#include "serve/session_report.hpp"
#include "text/said.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

constexpr auto kFrameInterval = std::chrono::milliseconds(33);  // about 30 events a second
// The longest a stream with nothing to say stays silent: then it sends a comment.
constexpr auto kQuietStream = std::chrono::seconds(2);
constexpr std::size_t kMostBody = 64 * 1024;  // bytes of a request's body
// Bytes of a measurement file a page sends: a phone's CSVs of minutes at 500 Hz, a phyphox zip, a
// short phone video (a longer one is for frictionlab estimate on the student's machine).
constexpr std::size_t kMostUpload = 32 * 1024 * 1024;
// A report's body: the largest upload in base64, and the rest of the request.
constexpr std::size_t kMostReportBody = kMostUpload / 3 * 4 + 4 + kMostBody;
// Measurement files taken at once, from their first byte to the answer: each holds up to
// kMostUpload of memory while it comes, and a video's tracking takes a core for seconds.
constexpr int kMostUploadsAtOnce = 2;
// Whether the request this thread answers holds one of those places (lab_server's pre-routing
// handler takes it before the body is read; the bounded server's request-done hook gives it back).
thread_local bool t_holds_upload = false;
constexpr std::size_t kMostHead = 16 * 1024;  // bytes of a request's line and headers together
// Each stream holds a thread while its page listens: two streams a session (a page reloading)
// and some for the other requests.
std::size_t thread_count(int max_sessions) {
  return static_cast<std::size_t>(2 * max_sessions + 8);
}

// Whether a request carries the server's token (none set: every request does).
bool carries_token(const httplib::Request& req, const std::string& token) {
  if (token.empty()) return true;
  return req.get_param_value("token") == token ||
         req.get_header_value("X-Frictionlab-Token") == token;
}

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

// The key a request carries for its session: the header X-Session-Key, or for a GET ?key= (a
// stream and a download are addresses, which carry no header). A control or an end takes the
// header only: a download's link shared by its student does not control the session.
std::string session_key_of(const httplib::Request& req) {
  if (req.has_header("X-Session-Key")) return req.get_header_value("X-Session-Key");
  return req.method == "GET" ? req.get_param_value("key") : std::string();
}

// Makes the reply say "Connection: close" (the bounded server ends the connection after it).
// The request is the library's own object, not a const one; the handler sees it through a
// const reference.
void say_connection_ends(const httplib::Request& req) {
  auto& headers = const_cast<httplib::Request&>(req).headers;
  headers.erase("Connection");
  headers.emplace("Connection", "close");
}

void send_body_too_large(httplib::Response& res, std::size_t most = kMostBody) {
  send_json(res, 413,
            error_json(most == kMostUpload
                           ? fmt::format("the file is larger than {} MiB, the most the lab's "
                                         "server takes: estimate it with frictionlab estimate on "
                                         "your machine, or send a shorter recording",
                                         most / (1024 * 1024))
                           : fmt::format("the request's body is larger than {} KiB, the most the "
                                         "lab takes: send a smaller one",
                                         most / 1024)));
}

// A body beyond the bound, sent in chunks the stream let through with their framing: 413.
bool refuse_large_body(const httplib::Request& req, httplib::Response& res) {
  if (req.body.size() <= kMostBody) return false;
  send_body_too_large(res);
  return true;
}

std::string event(const char* name, const json& data) {
  return fmt::format("event: {}\ndata: {}\n\n", name, data.dump());
}

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "::1" || host == "localhost";
}

std::string content_type(const std::string& name) {
  if (name.ends_with(".json")) return "application/json";
  if (name.ends_with(".csv")) return "text/csv";
  return "application/octet-stream";
}

}  // namespace

struct LabServer::Impl {
  explicit Impl(ServeOptions o)
      : options(std::move(o)),
        may_choose_port(options.pages_choose_port.value_or(is_loopback(options.host))),
        rate(options.requests_per_second, 3.0 * options.requests_per_second) {}

  ServeOptions options;
  const bool may_choose_port;
  RateLimit rate;
  BoundedServer server{kMostHead, kMostBody};
  PathScrubber public_paths;
  // An open session and its key: only a request that carries the key controls it.
  struct OpenSession {
    std::shared_ptr<LabSession> session;
    std::string key;
  };
  mutable std::mutex mutex;
  std::map<std::string, OpenSession> sessions;
  std::mt19937_64 ids{std::random_device{}()};
  std::atomic<bool> stopping{false};
  std::atomic<bool> listening{false};
  std::atomic<int> streams{0};
  std::atomic<int> uploads{0};  // measurement files being received or estimated
  // The live rig: the port open or last open (replaced when a page opens another).
  mutable std::mutex rig_mutex;
  std::shared_ptr<BoardFeed> rig;

  std::shared_ptr<BoardFeed> current_board() const {
    const std::lock_guard lock(rig_mutex);
    return rig;
  }
  // Opens `port`, closing the one open (outside the lock: its reader stops within 0.1 s).
  void open_rig(const std::string& port) {
    auto feed = std::make_shared<BoardFeed>(port, options.serial_baud, options.record_dir,
                                            options.most_rig_log_bytes);
    std::shared_ptr<BoardFeed> old;
    {
      const std::lock_guard lock(rig_mutex);
      old = std::exchange(rig, std::move(feed));
    }
    if (old) old->close();
  }
  std::vector<std::string> ports() const {
    std::vector<std::string> out = list_serial_ports(options.device_dir);
    if (!options.serial_port.empty() &&
        std::find(out.begin(), out.end(), options.serial_port) == out.end())
      out.insert(out.begin(), options.serial_port);
    return out;
  }
  json rig_status_json() const;
  std::vector<ClassRow> class_rows() const;

  // The session a request names when it carries the session's key; else a 404 (no such
  // session) or a 403 (not its key) said, and null.
  std::shared_ptr<LabSession> find(const httplib::Request& req, httplib::Response& res) const {
    OpenSession found;
    {
      const std::lock_guard lock(mutex);
      const auto it = sessions.find(req.matches[1]);
      if (it != sessions.end()) found = it->second;
    }
    if (!found.session) {
      send_json(res, 404, error_json(said("server-no-session")));
      return nullptr;
    }
    const std::string given = session_key_of(req);
    if (!same_key(found.key, given)) {
      send_json(res, 403,
                error_json(fmt::format(
                    "session {} is controlled only by the page that opened it: this request {}; "
                    "send the key POST /api/sessions answered (the header X-Session-Key; ?key= "
                    "only for a stream or a download), or open a session of your own",
                    std::string(req.matches[1]),
                    given.empty() ? "carries no session key" : "carries another key")));
      return nullptr;
    }
    return found.session;
  }
  // Takes the sessions out of the table under the lock, and lets them go after it: a session's
  // end gives its memory back (~LabSession), which must not hold up the other pages.
  std::vector<std::shared_ptr<LabSession>> take_out(
      const std::function<bool(const std::string&, const LabSession&)>& which) {
    std::vector<std::shared_ptr<LabSession>> out;
    const std::lock_guard lock(mutex);
    for (auto it = sessions.begin(); it != sessions.end();) {
      if (which(it->first, *it->second.session)) {
        out.push_back(std::move(it->second.session));
        it = sessions.erase(it);
      } else {
        ++it;
      }
    }
    return out;
  }
  void end_idle() {
    const auto now = Clock::now();
    const auto idle = std::chrono::duration<double>(options.idle_seconds);
    take_out([&](const std::string&, const LabSession& s) { return now - s.last_seen() > idle; });
  }
  bool full() const {
    const std::lock_guard lock(mutex);
    return static_cast<int>(sessions.size()) >= options.max_sessions;
  }
  // 503: a page beyond the limit is told so plainly, never left hanging.
  void refuse_full(httplib::Response& res) const {
    json body = error_json(said("server-full", {arg("sessions", options.max_sessions)}));
    body["refused"] = true;
    send_json(res, 503, body);
  }
  void routes();
  void create(const httplib::Request& req, httplib::Response& res);
  void estimate(const httplib::Request& req, httplib::Response& res);
  // Every error's answer (the error handler's): JSON naming the server's folders by what they
  // are; a request past the stream's bounds (bounded_server.hpp) answered so, on a connection
  // that then ends.
  httplib::Server::HandlerResponse answer_error(const httplib::Request& req,
                                                httplib::Response& res);
  // A measurement file takes one of kMostUploadsAtOnce places before its body is read; false
  // (answered 503, its body left unread) when none is free.
  bool take_upload_place(const httplib::Request& req, httplib::Response& res);
  // After each request: the place its file held, if it held one.
  void give_back_upload_place();
  void stream(const std::shared_ptr<LabSession>& session, httplib::Response& res);
  void control(LabSession& session, const httplib::Request& req, httplib::Response& res);
};

json LabServer::Impl::rig_status_json() const {
  return live_rig_json(current_board().get(),
                       may_choose_port ? ports() : std::vector<std::string>{}, may_choose_port,
                       options.serial_baud);
}

std::vector<ClassRow> LabServer::Impl::class_rows() const {
  std::vector<std::pair<std::string, std::shared_ptr<LabSession>>> open;
  {
    const std::lock_guard lock(mutex);
    open.reserve(sessions.size());
    for (const auto& [id, open_session] : sessions) open.emplace_back(id, open_session.session);
  }
  std::sort(open.begin(), open.end(),
            [](const auto& a, const auto& b) { return a.second->created() < b.second->created(); });
  std::vector<ClassRow> rows;
  const Clock::time_point now = Clock::now();
  const auto listed = std::chrono::duration<double>(options.listed_seconds);
  for (const auto& [id, session] : open)
    if (now - session->last_seen() <= listed)
      rows.push_back(
          {id, session->name(), session->scene(), session->rig_shared(), session->standing()});
  return rows;
}

void LabServer::Impl::routes() {
  server.Get("/api/lab", [this](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200,
              lab_json(list_scenes(options.scenes_dir), paper_table_in(options.asset_dir),
                       options.version));
  });
  server.Post("/api/sessions",
              [this](const httplib::Request& req, httplib::Response& res) { create(req, res); });
  const std::string session = "/api/sessions/([0-9a-f]{1,32})";
  server.Get(session + "/stream", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = find(req, res);
    if (!s) return;
    stream(s, res);
  });
  server.Post(session + "/control", [this](const httplib::Request& req, httplib::Response& res) {
    if (refuse_large_body(req, res)) return;
    const auto s = find(req, res);
    if (!s) return;
    control(*s, req, res);
  });
  // A report may carry the student's measurement file, in base64.
  server.allow_larger_body("/api/sessions/*/report", kMostReportBody);
  server.Post(session + "/report", [this](const httplib::Request& req, httplib::Response& res) {
    if (req.body.size() > kMostReportBody) return send_body_too_large(res, kMostReportBody);
    const auto s = find(req, res);
    if (!s) return;
    const ReportAnswer answer = session_report(*s, req.body, options.asset_dir, options.version);
    if (answer.status != 200) return send_json(res, answer.status, answer.body);
    res.set_header("Content-Disposition", "attachment; filename=\"report.html\"");
    res.set_content(answer.html, "text/html; charset=utf-8");
  });
  server.Get(session + "/files/([A-Za-z0-9_.-]{1,64})",
             [this](const httplib::Request& req, httplib::Response& res) {
               const auto s = find(req, res);
               if (!s) return;
               const std::string name = req.matches[2];
               const std::optional<std::string> text = s->file(name);
               if (!text)
                 return send_json(res, 404, missing_file_json(name, options.most_recorded_seconds));
               res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
               res.set_content(*text, content_type(name));
             });
  server.Get("/api/rig", [this](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, rig_status_json());
  });
  server.allow_larger_body("/api/estimate", kMostUpload);
  server.Post("/api/estimate",
              [this](const httplib::Request& req, httplib::Response& res) { estimate(req, res); });
  server.Post("/api/rig", [this](const httplib::Request& req, httplib::Response& res) {
    if (refuse_large_body(req, res)) return;
    const auto read = read_rig_body(req.body);
    if (const auto* refusal = std::get_if<BodyRefusal>(&read))
      return send_json(res, 400, error_json(refusal->message));
    const RigCommand& command = std::get<RigCommand>(read);
    if (!may_choose_port)
      return send_json(
          res, 403,
          error_json("this server is shared: a page may neither open nor close its serial "
                     "ports; the rig's port is the one its --serial names"));
    if (command.action == RigCommand::Action::kClose) {
      if (const auto feed = current_board()) feed->close();
      return send_json(res, 200, rig_status_json());
    }
    const std::vector<std::string> known = ports();
    if (std::find(known.begin(), known.end(), command.port) == known.end())
      return send_json(
          res, 400,
          error_json(fmt::format("no serial port {} here: expected one of GET /api/rig's ports "
                                 "({}); is the board plugged in?",
                                 json(command.port).dump(),
                                 known.empty() ? std::string("none now")
                                               : fmt::format("{}", fmt::join(known, ", ")))));
    open_rig(command.port);
    send_json(res, 200, rig_status_json());
  });
  server.Get("/api/rig/log", [this](const httplib::Request&, httplib::Response& res) {
    const std::shared_ptr<BoardFeed> feed = current_board();
    const BoardFeedStatus status = feed ? feed->status() : BoardFeedStatus{};
    if (!feed || status.lines == 0)
      return send_json(res, 404, error_json("no rig log yet: no line has come from a serial port"));
    res.set_header("Content-Disposition", "attachment; filename=\"" + status.log_name + "\"");
    res.set_content(feed->raw_log(), "text/plain; charset=utf-8");
  });
  server.Get("/api/class", [this](const httplib::Request&, httplib::Response& res) {
    const std::shared_ptr<BoardFeed> feed = current_board();
    send_json(res, 200,
              class_json(class_rows(), paper_table_in(options.asset_dir),
                         feed ? std::optional<BoardFeedStatus>(feed->status()) : std::nullopt));
  });
  server.Get("/api/class.csv", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Content-Disposition", "attachment; filename=\"class.csv\"");
    res.set_content(class_csv(class_rows(), paper_table_in(options.asset_dir)), "text/csv");
  });
  server.Delete(session, [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = find(req, res);
    if (!s) return;
    const std::string id = req.matches[1];
    const bool ended =
        !take_out([&](const std::string& key, const LabSession&) { return key == id; }).empty();
    send_json(res, ended ? 200 : 404,
              ended ? json{{"ended", true}} : error_json("no such session"));
  });
}

void LabServer::Impl::estimate(const httplib::Request& req, httplib::Response& res) {
  if (!req.has_param("name"))
    return send_json(res, 400,
                     error_json("expected the file's name as ?name= (e.g. "
                                "/api/estimate?name=phone.csv), found none"));
  MeasurementUpload upload{req.get_param_value("name"), req.body, std::nullopt, std::nullopt};
  if (req.has_param("spacing")) upload.spacing = req.get_param_value("spacing");
  if (req.has_param("h_c")) upload.h_c = req.get_param_value("h_c");
  const UploadAnswer answer = estimate_upload(upload, options.asset_dir);
  send_json(res, answer.status, answer.body);
}

httplib::Server::HandlerResponse LabServer::Impl::answer_error(const httplib::Request& req,
                                                               httplib::Response& res) {
  const RequestBound passed = BoundedServer::bound_passed();
  if (passed == RequestBound::kBodyTooLarge || res.status == 413) {
    say_connection_ends(req);
    // cpp-httplib reads a form's body (curl's default type) up to 8 KiB only.
    if (passed != RequestBound::kBodyTooLarge &&
        req.get_header_value("Content-Type").starts_with("application/x-www-form-urlencoded")) {
      send_json(res, 413,
                error_json("a form's body is read up to 8 KiB only: send the file itself "
                           "as the body, with Content-Type: application/octet-stream"));
      return httplib::Server::HandlerResponse::Handled;
    }
    send_body_too_large(res, server.most_body_bytes(req.path));
    return httplib::Server::HandlerResponse::Handled;
  }
  if (passed == RequestBound::kHeadTooLarge) {
    say_connection_ends(req);
    send_json(res, 431,
              error_json(fmt::format("the request's line and headers are larger than {} KiB, "
                                     "the most the lab takes",
                                     kMostHead / 1024)));
    return httplib::Server::HandlerResponse::Handled;
  }
  if (res.get_header_value("Content-Type") != "application/json")
    return httplib::Server::HandlerResponse::Unhandled;
  json body = json::parse(res.body, nullptr, /*allow_exceptions=*/false);
  if (body.is_discarded()) return httplib::Server::HandlerResponse::Unhandled;
  send_json(res, res.status, public_paths.scrubbed_body(std::move(body)));
  return httplib::Server::HandlerResponse::Handled;
}

bool LabServer::Impl::take_upload_place(const httplib::Request& req, httplib::Response& res) {
  if (uploads.fetch_add(1) < kMostUploadsAtOnce) {
    t_holds_upload = true;
    return true;
  }
  uploads.fetch_sub(1);
  say_connection_ends(req);
  send_json(res, 503, error_json(said("server-reading-files")));
  return false;
}

void LabServer::Impl::give_back_upload_place() {
  if (!t_holds_upload) return;
  t_holds_upload = false;
  uploads.fetch_sub(1);
}

void LabServer::Impl::create(const httplib::Request& req, httplib::Response& res) {
  if (refuse_large_body(req, res)) return;
  // A body the lab cannot take is refused for what it is, even when the lab is full.
  const auto read = read_session_body(req.body);
  if (const auto* refusal = std::get_if<BodyRefusal>(&read))
    return send_json(res, 400, refusal_json(*refusal));
  if (full()) return refuse_full(res);
  SessionOpening opening = open_session(std::get<SessionBody>(read), options.scenes_dir,
                                        options.asset_dir, options.most_recorded_seconds);
  if (!opening.session) return send_json(res, 400, opening.body);
  OpenSession open{std::move(opening.session), new_session_key()};
  json out{{"id", ""}, {"key", open.key}, {"rig", std::move(opening.body["rig"])}};
  {
    // Counted again where the session is added: two pages may have asked at once.
    const std::lock_guard lock(mutex);
    if (static_cast<int>(sessions.size()) >= options.max_sessions) return refuse_full(res);
    std::string id;
    do {
      id = fmt::format("{:016x}", ids());
    } while (sessions.contains(id));
    out["id"] = id;
    sessions.emplace(std::move(id), std::move(open));
  }
  send_json(res, 201, out);
}

void LabServer::Impl::stream(const std::shared_ptr<LabSession>& session, httplib::Response& res) {
  res.set_header("Cache-Control", "no-cache");
  struct StreamState {
    explicit StreamState(const CompiledRig& rig) : board_watch(BoardWatch::set_up_for(rig)) {}
    std::optional<int> generation;
    Clock::time_point next = Clock::now();
    Clock::time_point written = Clock::now();  // the last bytes written
    BoardWatch board_watch;                    // the live rig with this session's spacing
  };
  auto state = std::make_shared<StreamState>(session->rig());
  ++streams;
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, session, state](std::size_t, httplib::DataSink& sink) {
        if (!stopping) {
          std::this_thread::sleep_until(state->next);
          state->next = std::max(state->next + kFrameInterval, Clock::now());
        }
        if (stopping) {
          const std::string bye =
              event("closed", {{"message",
                                "the lab's server was stopped: its sessions ended; "
                                "download what you need before it stops next time"}});
          sink.write(bye.data(), bye.size());
          return false;
        }
        std::string out;
        for (const SessionEvent& e : session_events(*session, Clock::now(), state->generation))
          out += event(e.name.c_str(), e.data);
        if (const std::shared_ptr<BoardFeed> feed = current_board())
          if (const std::optional<json> watched = state->board_watch.next(feed))
            out += event("rig", *watched);
        // Nothing changed (a paused run): nothing is sent, but a comment now and then, which
        // EventSource ignores, so that a client that has gone is found out.
        const Clock::time_point now = Clock::now();
        if (out.empty() && now - state->written < kQuietStream) return true;
        if (out.empty()) out = ":\n\n";
        state->written = now;
        // A client that has gone: the write fails and the stream ends; the session stays for
        // its idle time (the page may come back).
        return sink.write(out.data(), out.size());
      },
      [this](bool) { --streams; });
}

void LabServer::Impl::control(LabSession& session, const httplib::Request& req,
                              httplib::Response& res) {
  const auto read = read_control_body(req.body);
  if (const auto* refusal = std::get_if<BodyRefusal>(&read))
    return send_json(res, 400, refusal_json(*refusal));
  send_json(res, 200, session.control(std::get<ControlCommand>(read), Clock::now()));
}

LabServer::LabServer(ServeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  httplib::Server& s = impl_->server;
  const std::size_t threads = thread_count(impl_->options.max_sessions);
  s.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  // cpp-httplib's own options add SO_REUSEPORT, with which a second server on a port in use
  // binds it too and shares its requests: SO_REUSEADDR alone lets a port be bound again after
  // its server ended, never while one listens on it.
  s.set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  // The folders a message may name, by what they are (the scenes' files by their names alone).
  PathScrubber& paths = impl_->public_paths;
  paths.add(impl_->options.scenes_dir, "", "the scenes folder");
  paths.add(impl_->options.asset_dir, "assets/", "assets");
  paths.add(impl_->options.web_dir, "web/", "web");
  paths.add(impl_->options.record_dir, "record/", "the record folder");
  if (const char* home = std::getenv("HOME")) paths.add(home, "~/", "~");
  std::error_code here_unknown;
  paths.add(std::filesystem::current_path(here_unknown).string(), "", ".");
  // Errors are answered before the library compresses them (Impl::answer_error).
  s.set_error_handler(httplib::Server::HandlerWithResponse(
      [this](const httplib::Request& req, httplib::Response& res) {
        return impl_->answer_error(req, res);
      }));
  s.set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
        std::string what = "an internal error";
        try {
          std::rethrow_exception(ep);
        } catch (const std::exception& e) {
          what = std::string("internal error: ") + e.what();
        } catch (...) {
        }
        send_json(res, 500, error_json(what));
      });
  // cpp-httplib compresses with brotli when a browser accepts it, at brotli's highest quality:
  // 3 s for the page's 730 kB script on this machine. Its gzip takes milliseconds for the same
  // 200 kB: the page gets gzip. (The request is the library's own object, not a const one; the
  // handler only sees it through a const reference.)
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    // A shared server's API answers only to its token; the page and the parts need none.
    if (req.path.starts_with("/api/") && !carries_token(req, impl_->options.token)) {
      send_json(res, 403,
                error_json("this server needs its token: open the address its owner gave, "
                           "the one ending in ?token=..."));
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.path.starts_with("/api/")) impl_->end_idle();
    if (req.path == "/api/estimate" && req.method == "POST" && !impl_->take_upload_place(req, res))
      return httplib::Server::HandlerResponse::Handled;
    // Each client's share: a page that asks too fast waits, and the others do not.
    double wait_s = 0.0;
    if (req.path.starts_with("/api/") &&
        !impl_->rate.allow(req.remote_addr, Clock::now(), &wait_s)) {
      res.set_header("Retry-After", std::to_string(static_cast<int>(std::ceil(wait_s))));
      send_json(res, 429,
                error_json(said("server-too-many", {arg("address", req.remote_addr),
                                                    arg("per_second", impl_->rate.per_second()),
                                                    arg("wait_s", to_decimal_places(wait_s, 1))})));
      return httplib::Server::HandlerResponse::Handled;
    }
    auto& headers = const_cast<httplib::Request&>(req).headers;
    for (auto it = headers.begin(); it != headers.end(); ++it) {
      if (it->first == "Accept-Encoding" && it->second.find("br") != std::string::npos) {
        std::string accepted;
        for (std::size_t start = 0; start < it->second.size();) {
          std::size_t end = it->second.find(',', start);
          if (end == std::string::npos) end = it->second.size();
          std::string token = it->second.substr(start, end - start);
          token.erase(0, token.find_first_not_of(' '));
          if (!token.starts_with("br")) accepted += (accepted.empty() ? "" : ", ") + token;
          start = end + 1;
        }
        it->second = accepted;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  impl_->server.on_request_done([this] { impl_->give_back_upload_place(); });
  impl_->routes();
  if (!impl_->options.web_dir.empty() && !s.set_mount_point("/", impl_->options.web_dir))
    throw std::runtime_error("the page's folder " + impl_->options.web_dir +
                             " is missing: build the page (cmake --build) or give --web DIR");
  const std::string parts = (std::filesystem::path(impl_->options.asset_dir) / "lego").string();
  s.set_mount_point("/parts", parts);
  s.set_file_extension_and_mimetype_mapping("glb", "model/gltf-binary");
  s.set_file_extension_and_mimetype_mapping("mjs", "text/javascript");
  if (!impl_->options.serial_port.empty()) impl_->open_rig(impl_->options.serial_port);
}

LabServer::~LabServer() {
  stop();
}

int LabServer::bind() {
  const ServeOptions& o = impl_->options;
  if (o.port == 0) {
    const int port = impl_->server.bind_to_any_port(o.host);
    if (port < 0) throw std::runtime_error("could not listen on " + o.host);
    return port;
  }
  errno = 0;
  if (impl_->server.bind_to_port(o.host, o.port)) return o.port;
  // cpp-httplib says only that it failed; bind()'s errno is left as it was.
  const int why = errno;
  if (why == EADDRINUSE)
    throw std::runtime_error(fmt::format(
        "port {} on {} is in use: another program (perhaps another frictionlab serve) listens "
        "on it; stop that one, or give another port (--port {}), or --port 0 for any free one",
        o.port, o.host, o.port == 65535 ? 8080 : o.port + 1));
  if (why == EACCES)
    throw std::runtime_error(fmt::format(
        "port {} on {} needs the administrator's rights (ports below 1024 do); give a port from "
        "1024 on (--port 8080), or --port 0 for any free one",
        o.port, o.host));
  throw std::runtime_error(
      fmt::format("could not listen on {}:{}{}; give another --host or --port, or --port 0 for "
                  "any free one",
                  o.host, o.port, why != 0 ? ": " + std::string(std::strerror(why)) : ""));
}

// cpp-httplib's stop() does nothing to a server that has not begun to listen, which would then
// listen forever: listen() says it is about to before it looks whether it was stopped, and stop()
// says so before it looks whether it listens, so one of them sees the other (both sequentially
// consistent), and stop() repeats until listen() has returned.
void LabServer::listen() {
  impl_->listening = true;
  if (!impl_->stopping) impl_->server.listen_after_bind();
  impl_->listening = false;
}

void LabServer::stop() {
  const bool first = !impl_->stopping.exchange(true);
  // The streams say goodbye (each within a frame), the rig's log is written whole.
  const auto deadline = Clock::now() + 4 * kFrameInterval;
  while (first && impl_->streams > 0 && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (const std::shared_ptr<BoardFeed> feed = impl_->current_board()) feed->close();
  while (impl_->listening) {
    impl_->server.stop();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::optional<std::string> LabServer::rig_record_path() const {
  const std::shared_ptr<BoardFeed> feed = impl_->current_board();
  if (!feed || feed->record_path().empty()) return std::nullopt;
  return feed->record_path();
}

int LabServer::sessions() const {
  const std::lock_guard lock(impl_->mutex);
  return static_cast<int>(impl_->sessions.size());
}

}  // namespace fl::serve
