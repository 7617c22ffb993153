#include "serve/api_requests.hpp"

#include <nlohmann/json.hpp>

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

}  // namespace

std::variant<SessionRequest, BodyRefusal> read_session_body(std::string_view text) {
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  SessionRequest request;
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
  return request;
}

std::variant<ControlCommand, BodyRefusal> read_control_body(std::string_view text) {
  auto parsed = object_of(text);
  if (auto* refusal = std::get_if<BodyRefusal>(&parsed)) return *refusal;
  const json& body = std::get<json>(parsed);
  ControlCommand command;
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
        "expected {\"action\": \"play\", \"pause\", \"step\" or \"reset\"} or {\"speed\": 1, "
        "0.25 or 0.0625}, found " +
        quoted(body)};
  return command;
}

}  // namespace fl::serve
