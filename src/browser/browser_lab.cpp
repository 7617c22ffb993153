#include "browser/browser_lab.hpp"

#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "hall_log/serial_port.hpp"
#include "lab/request/lab_data.hpp"
#include "serve/api_json.hpp"
#include "serve/api_requests.hpp"
#include "serve/measurement_upload.hpp"
#include "serve/session_events.hpp"
#include "serve/session_opening.hpp"
#include "serve/session_report.hpp"
#include "text/said.hpp"

namespace fl::browser {
namespace {

Answer no_such_session() {
  return {404, serve::error_json(said("server-no-session"))};
}

}  // namespace

BrowserLab::BrowserLab(std::string scenes_dir, std::string asset_dir, std::string version)
    : scenes_dir_(std::move(scenes_dir)),
      asset_dir_(std::move(asset_dir)),
      version_(std::move(version)) {}

Answer BrowserLab::lab() const {
  return {200, serve::lab_json(list_scenes(scenes_dir_), paper_table_in(asset_dir_), version_)};
}

BrowserLab::Open* BrowserLab::find(const std::string& id) {
  const auto it = sessions_.find(id);
  return it == sessions_.end() ? nullptr : &it->second;
}

Answer BrowserLab::create_session(std::string_view body) {
  const auto read = serve::read_session_body(body);
  if (const auto* refusal = std::get_if<serve::BodyRefusal>(&read))
    return {400, serve::refusal_json(*refusal)};
  serve::SessionOpening opening = serve::open_session(
      std::get<serve::SessionBody>(read), scenes_dir_, asset_dir_, serve::kMostRecordedSeconds);
  if (!opening.session) return {400, std::move(opening.body)};
  const std::string id = fmt::format("{:016x}", next_id_++);
  const CompiledRig& rig = opening.session->rig();
  sessions_.emplace(id, Open{std::move(opening.session), std::nullopt,
                             serve::BoardWatch(serve::BoardWatch::set_up_for(rig))});
  return {201, {{"id", id}, {"key", ""}, {"rig", std::move(opening.body["rig"])}}};
}

Answer BrowserLab::events(const std::string& id) {
  Open* open = find(id);
  if (open == nullptr) return no_such_session();
  nlohmann::json out = nlohmann::json::array();
  for (serve::SessionEvent& e :
       serve::session_events(*open->session, serve::Clock::now(), open->generation))
    out.push_back({{"event", std::move(e.name)}, {"data", std::move(e.data)}});
  if (rig_)
    if (std::optional<nlohmann::json> watched = open->rig_watch.next(rig_))
      out.push_back({{"event", "rig"}, {"data", std::move(*watched)}});
  return {200, std::move(out)};
}

Answer BrowserLab::control(const std::string& id, std::string_view body) {
  Open* open = find(id);
  if (open == nullptr) return no_such_session();
  const auto read = serve::read_control_body(body);
  if (const auto* refusal = std::get_if<serve::BodyRefusal>(&read))
    return {400, serve::refusal_json(*refusal)};
  return {200, open->session->control(std::get<serve::ControlCommand>(read), serve::Clock::now())};
}

Answer BrowserLab::file(const std::string& id, const std::string& name) {
  Open* open = find(id);
  if (open == nullptr) return no_such_session();
  const std::optional<std::string> text = open->session->file(name);
  if (!text) return {404, serve::missing_file_json(name, serve::kMostRecordedSeconds)};
  return {200, {{"text", *text}}};
}

Answer BrowserLab::report(const std::string& id, std::string_view body) {
  Open* open = find(id);
  if (!open) return no_such_session();
  const serve::ReportAnswer answer =
      serve::session_report(*open->session, body, asset_dir_, version_);
  if (answer.status != 200) return {answer.status, answer.body};
  return {200, {{"html", answer.html}}};
}

Answer BrowserLab::end(const std::string& id) {
  if (sessions_.erase(id) == 0) return no_such_session();
  return {200, {{"ended", true}}};
}

Answer BrowserLab::estimate(const std::string& name, std::string bytes,
                            std::optional<std::string> spacing,
                            std::optional<std::string> h_c) const {
  const serve::UploadAnswer answer = serve::estimate_upload(
      {name, std::move(bytes), std::move(spacing), std::move(h_c)}, asset_dir_);
  return {answer.status, answer.body};
}

Answer BrowserLab::rig() const {
  return {200, serve::live_rig_json(rig_.get(), {}, true, kFirmwareBaud)};
}

Answer BrowserLab::rig_open(const std::string& port, int baud) {
  if (const std::optional<std::string> why = baud_problem(baud))
    return {400, serve::error_json(*why)};
  if (rig_) rig_->close();
  rig_ = std::make_shared<serve::BoardFeed>(serve::BoardFeed::FedFromOutside{}, port, baud,
                                            serve::kMostRigLogBytes);
  return rig();
}

Answer BrowserLab::rig_bytes(std::string_view bytes, bool ended) {
  if (!rig_) return {409, serve::error_json("no port is open: open one before sending its bytes")};
  rig_->feed(bytes, ended);
  return rig();
}

Answer BrowserLab::rig_close() {
  if (rig_) rig_->close();
  return rig();
}

Answer BrowserLab::rig_log() const {
  const serve::BoardFeedStatus status = rig_ ? rig_->status() : serve::BoardFeedStatus{};
  if (!rig_ || status.lines == 0)
    return {404, serve::error_json("no rig log yet: no line has come from a serial port")};
  return {200, {{"name", status.log_name}, {"text", rig_->raw_log()}}};
}

}  // namespace fl::browser
