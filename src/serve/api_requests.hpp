// The API's request bodies read (docs/web-api.md): what a page asks, or what is wrong with the
// body, before anything runs. Any bytes give one or the other and never throw (a libFuzzer target
// holds it: tests/fuzz/api_body_fuzzer.cpp).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

#include "lab/report/report_content.hpp"
#include "lab/request/session_request.hpp"

namespace fl::serve {

// A body the API cannot take: what was expected, what was found.
struct BodyRefusal {
  explicit BodyRefusal(std::string what, std::string at = "")
      : message(std::move(what)), field(std::move(at)) {}
  std::string message;
  std::string field;  // the one field at fault ("" : the body as a whole)
};

// A 400's body for a refusal: {"error": what}, and with a field at fault, the problem by that
// field, shown beside its control.
nlohmann::json refusal_json(const BodyRefusal& refusal);

// The most `set` entries a session's body may carry.
inline constexpr std::size_t kMostSetEntries = 64;

// POST /api/sessions: {"scene": NAME, "set": ["key.path=value", ...], "name": WHO}: the run's
// request, and who runs it for the class's table ("" : not given).
struct SessionBody {
  SessionRequest request;
  std::string name;
};
// The most characters of a name; letters (any script), digits, spaces and . - _ ' , ( ).
inline constexpr std::size_t kMostNameCharacters = 40;
// A student's name for the class's table, by the one rule the page keeps too (web/src/
// student_name.ts; both held to tests/data/student_names.json): 1 to 40 characters, each an ASCII
// letter or digit, a character from U+00C0 to U+DFFF but U+2000 to U+2FFF (the letters of Latin,
// Greek, Cyrillic, Arabic, Indic and CJK scripts; no general punctuation, symbols, direction marks
// or emoji), a space, or . - _ ' , ( ) ("Smith, J.", "Anne-Marie (2B)"; the CSV quotes a comma),
// the first a letter or digit (so that no spreadsheet reads the
// class's CSV cell as a formula). `name` is valid UTF-8 (the JSON reader has checked it).
bool is_student_name(const std::string& name);
std::variant<SessionBody, BodyRefusal> read_session_body(std::string_view body);

// The slow-motion factors the page offers: 1, 0.25 and 0.0625.
inline bool is_speed(double speed) {
  return speed == 1.0 || speed == 0.25 || speed == 0.0625;
}

// POST /api/sessions/ID/control: {"action": "play" | "pause" | "step" | "reset"},
// {"speed": 1 | 0.25 | 0.0625}, or {"name": WHO} (who runs it, for the class's table, as the
// session's body gives it; "" takes it away).
struct ControlCommand {
  enum class Action { kPlay, kPause, kStep, kReset, kSpeed, kName };
  Action action = Action::kPause;
  double speed = 1.0;  // with kSpeed
  std::string name;    // with kName
};
std::variant<ControlCommand, BodyRefusal> read_control_body(std::string_view body);

// POST /api/rig: {"port": NAME} (a name GET /api/rig listed; checked by the server) or
// {"action": "close"}.
struct RigCommand {
  enum class Action { kOpen, kClose };
  Action action = Action::kClose;
  std::string port;  // with kOpen
};
std::variant<RigCommand, BodyRefusal> read_rig_body(std::string_view body);

// The most stopwatch timings a report's body may carry.
inline constexpr std::size_t kMostStopwatchTimings = 100;

// POST /api/sessions/ID/report: {"student": WHO, "stopwatch": [{"periods": N, "wall_s": S,
// "simulated_s": S or null}, ...], "language": "fr", "measurement": {MeasurementEstimate}}, each
// optional (the session's name; no timing; English; no measurement).
// A file a page sends inside a JSON body: {"name": "log.csv", "base64": "..."}.
struct SentFile {
  std::string name;   // as on the student's machine
  std::string bytes;  // decoded
};

struct ReportBody {
  std::optional<std::string> student;
  // "measurement": the page's "Your measurement", as POST /api/estimate answered it.
  std::optional<MeasuredSummary> measured;
  // "measurement_file": its file, read again for the report's signal and periods.
  std::optional<SentFile> measurement_file;
  std::string language = "en";  // checked against the lab's catalogues by the report's request
  std::vector<StopwatchTiming> stopwatch;
};
std::variant<ReportBody, BodyRefusal> read_report_body(std::string_view body);

}  // namespace fl::serve
