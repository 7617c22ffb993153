// libFuzzer target for the web API's request bodies (serve/api_requests.hpp: a session's, a
// control's, a report's, the live rig's): any bytes are read as a request or refused with a
// message, within the API's bounds; anything else (a crash, a sanitizer report, an exception, a
// hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "serve/api_requests.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto session = fl::serve::read_session_body(text);
  if (const auto* body = std::get_if<fl::serve::SessionBody>(&session)) {
    if (body->request.set.size() > fl::serve::kMostSetEntries) std::abort();
    if (body->name.size() > 4 * fl::serve::kMostNameCharacters) std::abort();
  } else if (std::get<fl::serve::BodyRefusal>(session).message.empty()) {
    std::abort();
  }
  const auto control = fl::serve::read_control_body(text);
  if (const auto* command = std::get_if<fl::serve::ControlCommand>(&control)) {
    if (!fl::serve::is_speed(command->speed)) std::abort();
  } else if (std::get<fl::serve::BodyRefusal>(control).message.empty()) {
    std::abort();
  }
  const auto report = fl::serve::read_report_body(text);
  if (const auto* body = std::get_if<fl::serve::ReportBody>(&report)) {
    if (body->stopwatch.size() > fl::serve::kMostStopwatchTimings) std::abort();
    for (const auto& timing : body->stopwatch)
      if (!(timing.periods >= 1 && timing.wall_s > 0)) std::abort();
  } else if (std::get<fl::serve::BodyRefusal>(report).message.empty()) {
    std::abort();
  }
  const auto rig = fl::serve::read_rig_body(text);
  if (const auto* refusal = std::get_if<fl::serve::BodyRefusal>(&rig);
      refusal != nullptr && refusal->message.empty()) {
    std::abort();
  }
  return 0;
}
