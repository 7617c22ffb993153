#include "serve/api_requests.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "text/base64.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

// A value as the message quotes it: at most 80 characters of its JSON.
std::string quoted(const json& value) {
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

// The body as a JSON object, or why not.
std::variant<json, BodyRefusal> object_of(std::string_view body) {
  json parsed = json::parse(body.begin(), body.end(), nullptr, /*allow_exceptions=*/false);
  if (parsed.is_discarded() || !parsed.is_object())
    return BodyRefusal{"expected a JSON object as the request's body, found " +
                       (body.empty() ? std::string("none") : "text that is not one")};
  return parsed;
}

// What a student's name is, for a refusal.
std::string name_expected() {
  return "expected a name of up to " + std::to_string(kMostNameCharacters) +
         " letters, digits, spaces and . - _ ' , ( ), beginning with a letter or digit";
}

std::variant<SentFile, BodyRefusal> read_sent_file(const json& value, const std::string& field) {
  const auto text = [&value](const char* key) -> const std::string* {
    const auto it = value.is_object() ? value.find(key) : value.end();
    return it != value.end() && it->is_string() ? it->get_ptr<const std::string*>() : nullptr;
  };
  const std::string* name = text("name");
  const std::string* base64 = text("base64");
  if (!name || !base64 || value.size() != 2 || name->empty() || name->size() > 255)
    return BodyRefusal{"expected \"" + field +
                           "\" as {\"name\": the file's name, \"base64\": its bytes in base64}, "
                           "found " +
                           quoted(value),
                       field};
  std::optional<std::string> bytes = decode_base64(*base64);
  if (!bytes)
    return BodyRefusal{"expected \"" + field +
                           ".base64\" as the file's bytes in base64 (as btoa writes them), found "
                           "characters that are not",
                       field};
  return SentFile{*name, std::move(*bytes)};
}

}  // namespace

json refusal_json(const BodyRefusal& refusal) {
  json out{{"error", refusal.message}};
  if (!refusal.field.empty())
    out["problems"].push_back(
        {{"field", refusal.field}, {"value", nullptr}, {"message", refusal.message}});
  return out;
}

bool is_student_name(const std::string& name) {
  std::size_t characters = 0;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if ((c & 0xC0) == 0x80) continue;  // a continuation byte: part of the character before
    ++characters;
    // Lead bytes C3 to ED but E2: U+00C0 to U+DFFF but U+2000 to U+2FFF.
    const bool letter_or_digit =
        (c >= 0xC3 && c <= 0xED && c != 0xE2) || (c < 0x80 && std::isalnum(c) != 0);
    if (characters == 1 && !letter_or_digit) return false;
    if (!letter_or_digit &&
        std::string_view(" .-_',()").find(static_cast<char>(c)) == std::string_view::npos)
      return false;
  }
  return characters >= 1 && characters <= kMostNameCharacters;
}

namespace {

// A student's name, or "" for none: the refusal of anything else, by `field`.
std::optional<BodyRefusal> name_or_none_refused(const json& value, const char* field) {
  const bool empty = value.is_string() && value.get<std::string>().empty();
  if (value.is_string() && (empty || is_student_name(value.get<std::string>())))
    return std::nullopt;
  return BodyRefusal{name_expected() + ", or \"\" for none, found " + quoted(value), field};
}

}  // namespace

std::variant<SessionBody, BodyRefusal> read_session_body(std::string_view text) {
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  SessionBody out;
  SessionRequest& request = out.request;
  const auto scene = body.find("scene");
  if (scene == body.end() || !scene->is_string())
    return BodyRefusal{"expected \"scene\": the name of a scene /api/lab offers"};
  request.scene = scene->get<std::string>();
  if (const auto set = body.find("set"); set != body.end()) {
    if (!set->is_array() || set->size() > kMostSetEntries)
      return BodyRefusal{"expected \"set\" as a list of at most " +
                         std::to_string(kMostSetEntries) + " texts \"key.path=value\""};
    for (const json& entry : *set) {
      if (!entry.is_string())
        return BodyRefusal{"expected each \"set\" entry as a text \"key.path=value\", found " +
                           quoted(entry)};
      request.set.push_back(entry.get<std::string>());
    }
  }
  if (const auto name = body.find("name"); name != body.end() && !name->is_null()) {
    if (!name->is_string() || !is_student_name(name->get<std::string>()))
      return BodyRefusal{name_expected() + ", found " + quoted(*name), "name"};
    out.name = name->get<std::string>();
  }
  return out;
}

std::variant<ControlCommand, BodyRefusal> read_control_body(std::string_view text) {
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  ControlCommand command;
  if (const auto name = body.find("name"); name != body.end()) {
    if (auto refusal = name_or_none_refused(*name, "name")) return *refusal;
    command.action = ControlCommand::Action::kName;
    command.name = name->get<std::string>();
    return command;
  }
  if (const auto speed = body.find("speed"); speed != body.end()) {
    if (!speed->is_number() || !is_speed(speed->get<double>()))
      return BodyRefusal{"expected \"speed\" as 1, 0.25 or 0.0625, found " + quoted(*speed)};
    command.action = ControlCommand::Action::kSpeed;
    command.speed = speed->get<double>();
    return command;
  }
  const auto action = body.find("action");
  const std::string name =
      action != body.end() && action->is_string() ? action->get<std::string>() : "";
  if (name == "play")
    command.action = ControlCommand::Action::kPlay;
  else if (name == "pause")
    command.action = ControlCommand::Action::kPause;
  else if (name == "step")
    command.action = ControlCommand::Action::kStep;
  else if (name == "reset")
    command.action = ControlCommand::Action::kReset;
  else
    return BodyRefusal{
        "expected {\"action\": \"play\", \"pause\", \"step\" or \"reset\"}, {\"speed\": 1, "
        "0.25 or 0.0625} or {\"name\": a student's name}, found " +
        quoted(body)};
  return command;
}

namespace {

// A MeasurementEstimate as POST /api/estimate answered it: its numbers finite, its counts whole.
std::variant<MeasuredSummary, BodyRefusal> read_measured(const json& m) {
  const BodyRefusal refused{
      "expected \"measurement\" as POST /api/estimate answered it (file, instrument, "
      "periods_used, period_s, mu_k, ...), found " +
          quoted(m),
      "measurement"};
  if (!m.is_object()) return refused;
  MeasuredSummary out;
  const auto text = [&m](const char* key, std::string& into, bool may_be_null) {
    const auto it = m.find(key);
    if (it == m.end()) return false;
    if (it->is_null()) return may_be_null;
    if (!it->is_string() || it->get<std::string>().size() > 256) return false;
    into = it->get<std::string>();
    return true;
  };
  const auto number = [&m](const char* key, double& into, double least) {
    const auto it = m.find(key);
    if (it == m.end() || !it->is_number()) return false;
    into = it->get<double>();
    return std::isfinite(into) && into >= least && into < 1e12;
  };
  const bool ok =
      text("file", out.file, false) && text("instrument", out.instrument, false) &&
      text("channel", out.channel, true) && number("samples", out.samples, 1) &&
      number("sample_rate_hz", out.sample_rate_hz, 0) && number("duration_s", out.duration_s, 0) &&
      number("periods_used", out.periods_used, 1) && number("period_s", out.period_s, 1e-9) &&
      number("period_std_s", out.period_std_s, 0) && number("period_sem_s", out.period_sem_s, 0) &&
      number("mu_k", out.mu_k, 0) && number("mu_k_err_quadrature", out.mu_k_err_quadrature, 0) &&
      number("mu_k_err_worst", out.mu_k_err_worst, 0) && number("spacing_m", out.spacing_m, 1e-9) &&
      out.periods_used == std::floor(out.periods_used) && out.samples == std::floor(out.samples);
  if (!ok) return refused;
  return out;
}

}  // namespace

std::variant<ReportBody, BodyRefusal> read_report_body(std::string_view text) {
  if (text.empty()) return ReportBody{};
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  ReportBody report;
  for (const auto& [key, value] : body.items())
    if (key != "student" && key != "stopwatch" && key != "language" && key != "measurement" &&
        key != "measurement_file")
      return BodyRefusal{
          "expected the keys \"student\", \"stopwatch\", \"language\", \"measurement\" and "
          "\"measurement_file\", found \"" +
          key + "\""};
  if (const auto measured = body.find("measurement"); measured != body.end()) {
    auto read = read_measured(*measured);
    if (auto* refusal = std::get_if<BodyRefusal>(&read)) return *refusal;
    report.measured = std::get<MeasuredSummary>(read);
  }
  if (const auto file = body.find("measurement_file"); file != body.end()) {
    auto read = read_sent_file(*file, "measurement_file");
    if (auto* refusal = std::get_if<BodyRefusal>(&read)) return *refusal;
    if (!report.measured)
      return BodyRefusal{
          "expected \"measurement\" beside \"measurement_file\": its spacing "
          "reads the file as POST /api/estimate read it",
          "measurement_file"};
    report.measurement_file = std::get<SentFile>(read);
  }
  if (const auto language = body.find("language"); language != body.end()) {
    const std::string code = language->is_string() ? language->get<std::string>() : "";
    const bool word = !code.empty() && code.size() <= 16 &&
                      std::all_of(code.begin(), code.end(),
                                  [](char c) { return (c >= 'a' && c <= 'z') || c == '-'; });
    if (!word)
      return BodyRefusal{
          "expected \"language\" as a language's code (\"en\", \"fr\"), found " + quoted(*language),
          "language"};
    report.language = code;
  }
  if (const auto student = body.find("student"); student != body.end()) {
    if (auto refusal = name_or_none_refused(*student, "student")) return *refusal;
    report.student = student->get<std::string>();
  }
  const auto stopwatch = body.find("stopwatch");
  if (stopwatch == body.end()) return report;
  if (!stopwatch->is_array() || stopwatch->size() > kMostStopwatchTimings)
    return BodyRefusal{"expected \"stopwatch\" as a list of at most " +
                           std::to_string(kMostStopwatchTimings) + " timings, found " +
                           quoted(*stopwatch),
                       "stopwatch"};
  for (const json& t : *stopwatch) {
    const auto number = [&t](const char* key) {
      const auto it = t.is_object() ? t.find(key) : t.end();
      return t.is_object() && it != t.end() && it->is_number() ? std::optional(it->get<double>())
                                                               : std::nullopt;
    };
    const std::optional<double> periods = number("periods"), wall = number("wall_s");
    const bool simulated_null =
        t.is_object() && t.contains("simulated_s") && t["simulated_s"].is_null();
    const std::optional<double> simulated = number("simulated_s");
    if (!periods || !wall || (!simulated && !simulated_null) ||
        !(*periods >= 1 && *periods <= 1000) || *periods != std::floor(*periods) ||
        !(*wall > 0 && *wall < 1e6) || (simulated && !(*simulated > 0 && *simulated < 1e7)))
      return BodyRefusal{
          "expected each timing as {\"periods\": 1 to 1000, \"wall_s\": a positive "
          "time, \"simulated_s\": a positive time or null}, found " +
              quoted(t),
          "stopwatch"};
    report.stopwatch.push_back({static_cast<int>(*periods), *wall, simulated});
  }
  return report;
}

std::variant<RigCommand, BodyRefusal> read_rig_body(std::string_view text) {
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  RigCommand command;
  const auto port = body.find("port");
  if (port != body.end() && port->is_string() && body.size() == 1) {
    command.action = RigCommand::Action::kOpen;
    command.port = port->get<std::string>();
    return command;
  }
  const auto action = body.find("action");
  if (action != body.end() && *action == "close" && body.size() == 1) return command;
  return BodyRefusal{
      "expected {\"port\": one of the ports GET /api/rig lists} or {\"action\": \"close\"}, "
      "found " +
      quoted(body)};
}

}  // namespace fl::serve
