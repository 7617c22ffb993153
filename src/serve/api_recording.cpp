#include "serve/api_recording.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "api/api_fields.hpp"
#include "hall_log/serial_port.hpp"
#include "io/input_error.hpp"
#include "lab/live/live_run.hpp"
#include "lab/logs/live_log_estimate.hpp"
#include "lab/request/lab_data.hpp"
#include "serve/api_json.hpp"
#include "serve/board_watch.hpp"
#include "serve/class_table.hpp"
#include "serve/lab_session.hpp"

namespace fl::serve {
namespace {

using nlohmann::json;

constexpr double kFramesPerSecond = 30.0;  // a step's simulated time, and a stream's pace
// The firmware's first line (tools/arduino), as a board sends it after its reset.
constexpr const char* kBoardHeader =
    "# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 raw_every=1";

struct OfferedScene {
  SceneEntry entry;
  std::string folder;
};

std::vector<OfferedScene> offered_scenes(const std::vector<std::string>& files) {
  std::vector<OfferedScene> out;
  for (const std::string& file : files) {
    const std::filesystem::path path(file);
    const std::string folder = path.parent_path().string();
    const std::vector<SceneEntry> entries = list_scenes(folder);
    const auto entry = std::find_if(entries.begin(), entries.end(), [&](const SceneEntry& e) {
      return e.name == path.stem().string();
    });
    if (entry == entries.end())
      throw std::invalid_argument(fmt::format(
          "{}: not a scene its folder offers (a scene named as its file's stem)", file));
    out.push_back({*entry, folder});
  }
  return out;
}

const OfferedScene* scene_named(const std::vector<OfferedScene>& scenes, const std::string& name) {
  for (const OfferedScene& s : scenes)
    if (s.entry.name == name) return &s;
  return nullptr;
}

// The run of one session as its stream sends it at 1x: the state at t = 0 (paused), then one
// state a frame interval until the run ends; the class's row at each.
json recorded_run(const SessionRequest& request, PreparedSession prepared, const PaperTable& table,
                  json& summary) {
  LabSession session(request.scene, std::move(prepared));
  const Clock::time_point t0{};
  json frames = json::array();
  const auto record = [&](const nlohmann::json& state) {
    const ClassRow row{"", "", request.scene, session.rig_shared(), session.standing()};
    frames.push_back(
        {{"state", state}, {"row", class_json({row}, table, std::nullopt)["sessions"][0]}});
  };
  record(*session.tick(t0).state);
  session.play(t0);
  const double frames_at_most = session.rig().world.duration * kFramesPerSecond + 10.0;
  for (int k = 1; k <= frames_at_most; ++k) {
    const auto now = t0 + std::chrono::nanoseconds(std::llround(k * 1e9 / kFramesPerSecond));
    const LabSession::Tick tick = session.tick(now);
    if (tick.state) record(*tick.state);
    if (tick.done) {
      summary = *tick.done;
      return frames;
    }
  }
  throw std::logic_error(fmt::format("{}: the run did not end", request.scene));
}

json recorded_setup(const SessionRequest& asked, const ApiRecordingRequest& request,
                    const std::vector<OfferedScene>& scenes, const PaperTable& table) {
  json out{{"scene", asked.scene}, {"set", asked.set}};
  const OfferedScene* scene = scene_named(scenes, asked.scene);
  if (scene == nullptr)
    throw std::invalid_argument(fmt::format("a set-up of {}, a scene not offered", asked.scene));
  SessionRequest run = asked;
  const bool timed = std::any_of(run.set.begin(), run.set.end(), [](const std::string& e) {
    return e.starts_with("world.duration=");
  });
  if (!timed && !request.duration_entry.empty()) run.set.push_back(request.duration_entry);
  std::optional<PreparedSession> prepared;
  try {
    prepared = prepare_session(run, scene->folder, request.asset_dir);
  } catch (const InputError& e) {
    out["status"] = 400;
    out["body"] = problems_json(e);
    return out;
  } catch (const std::invalid_argument& e) {
    out["status"] = 400;
    out["body"] = problems_json(e);
    return out;
  }
  out["status"] = 201;
  out["body"] = {{"rig", rig_json(asked.scene, *prepared->rig, prepared->accepts, table)}};
  json summary;
  out["frames"] = recorded_run(asked, std::move(*prepared), table, summary);
  out["summary"] = std::move(summary);
  return out;
}

// The board's run: its Hall samples as the firmware's lines would stamp them.
struct BoardSamples {
  std::vector<std::uint32_t> t_us;
  std::vector<std::uint16_t> adc;
};

BoardSamples board_samples(const ApiRecordingRequest& request,
                           const std::vector<OfferedScene>& scenes) {
  const OfferedScene* scene = scene_named(scenes, request.board.scene);
  if (scene == nullptr)
    throw std::invalid_argument(
        fmt::format("the board's scene {} is not offered", request.board.scene));
  const PreparedSession prepared = prepare_session(request.board, scene->folder, request.asset_dir);
  LiveRun run(prepared.rig, prepared.output);
  run.advance_to(1e9);
  const std::optional<std::string> hall = run.file("hall.csv");
  if (!hall) throw std::invalid_argument("the board's scene keeps no hall.csv");
  BoardSamples out;
  std::istringstream in(*hall);
  std::string line;
  std::getline(in, line);  // t_us,adc
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    out.t_us.push_back(static_cast<std::uint32_t>(std::stoul(line.substr(0, comma))));
    out.adc.push_back(static_cast<std::uint16_t>(std::stoul(line.substr(comma + 1))));
  }
  return out;
}

// What the rig's estimator judges in the board's samples with l = `spacing`: a change each time
// a period is judged or the geometry is recognised, at the number of samples it took.
json board_reading(const BoardSamples& board, double spacing, double gravity) {
  LiveLogEstimate live(
      LogSetUp{spacing, LogSetUp{}.spacing_err, gravity, fl_estimator::kAutoGeometry, std::nullopt},
      /*keep_samples=*/false);
  json changes = json::array();
  std::size_t sent = 0;
  fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry;
  for (std::size_t i = 0; i < board.adc.size(); ++i) {
    live.add(LogSample{
        .t_s = board.t_us[i] * 1e-6, .adc = board.adc[i], .line = static_cast<int>(i) + 3});
    // The event's reading is made only when it changes, not at each of the 40 000 samples.
    const std::vector<EstimatedPeriod>& periods = live.host().periods();
    const fl_estimator::Geometry now = live.host().estimator().geometry();
    if (periods.size() == sent && now == geometry) continue;
    json change{{"samples", i + 1}, {"periods", periods_json(periods, sent)}};
    change.update(board_reading_json(live));
    changes.push_back(std::move(change));
    sent = periods.size();
    geometry = now;
  }
  return {{"spacing", spacing}, {"changes", std::move(changes)}};
}

}  // namespace

json record_api(const ApiRecordingRequest& request) {
  const std::vector<OfferedScene> scenes = offered_scenes(request.scene_files);
  const PaperTable& table = paper_table_in(request.asset_dir);
  std::vector<SceneEntry> entries;
  for (const OfferedScene& s : scenes) entries.push_back(s.entry);
  json setups = json::array();
  std::map<double, double> spacings;  // l -> g of the sessions recorded
  for (const SessionRequest& asked : request.setups) {
    json setup = recorded_setup(asked, request, scenes, table);
    if (setup["status"] == 201) {
      const json& rig = setup["body"]["rig"];
      spacings[rig["spacing"].get<double>()] = rig["gravity"].get<double>();
    }
    setups.push_back(std::move(setup));
  }
  const BoardSamples board = board_samples(request, scenes);
  json readings = json::array();
  for (const auto& [spacing, gravity] : spacings)
    readings.push_back(board_reading(board, spacing, gravity));
  return {{"declaration", api::api_declaration_json()},
          {"lab", lab_json(entries, table, request.version)},
          {"frame_interval_s", 1.0 / kFramesPerSecond},
          {"setups", std::move(setups)},
          {"board",
           {{"header", kBoardHeader},
            {"baud", kFirmwareBaud},
            {"shown_s", BoardWatch::kShownSeconds},
            {"t_us", board.t_us},
            {"adc", board.adc},
            {"readings", std::move(readings)}}}};
}

}  // namespace fl::serve
