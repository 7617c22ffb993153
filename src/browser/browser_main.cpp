// The browser's build's entry (Emscripten, embind): the lab of browser_lab.hpp, one per worker,
// each call answering JSON text {"status": ..., "body": ...} as the server would (web/src/
// lab_worker.ts calls these). An exception a request did not expect is a 500 with its message, as
// the server's.
#include <emscripten/bind.h>

#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "browser/browser_lab.hpp"
#include "serve/api_json.hpp"
#include "serve/measurement_upload.hpp"
#include "tracking/given_video.hpp"
#include "tracking/track_video.hpp"

namespace fl::browser {
namespace {

std::unique_ptr<BrowserLab> g_lab;

template <class Ask>
std::string answered(Ask&& ask) {
  Answer answer;
  try {
    if (!g_lab) throw std::logic_error("the lab is not open: call open_lab first");
    answer = ask(*g_lab);
  } catch (const std::exception& e) {
    answer = {500, serve::error_json(std::string("internal error: ") + e.what())};
  }
  return nlohmann::json{{"status", answer.status}, {"body", std::move(answer.body)}}.dump();
}

std::optional<std::string> given(const std::string& value, bool is_given) {
  return is_given ? std::optional<std::string>(value) : std::nullopt;
}

void open_lab(const std::string& scenes_dir, const std::string& asset_dir) {
  g_lab = std::make_unique<BrowserLab>(scenes_dir, asset_dir,
                                       std::string("frictionlab ") + FRICTIONLAB_VERSION);
}

std::string lab() {
  return answered([](BrowserLab& lab) { return lab.lab(); });
}
std::string create_session(const std::string& body) {
  return answered([&](BrowserLab& lab) { return lab.create_session(body); });
}
std::string events(const std::string& id) {
  return answered([&](BrowserLab& lab) { return lab.events(id); });
}
std::string control(const std::string& id, const std::string& body) {
  return answered([&](BrowserLab& lab) { return lab.control(id, body); });
}
std::string file(const std::string& id, const std::string& name) {
  return answered([&](BrowserLab& lab) { return lab.file(id, name); });
}
std::string report(const std::string& id, const std::string& body) {
  return answered([&](BrowserLab& lab) { return lab.report(id, body); });
}
std::string end(const std::string& id) {
  return answered([&](BrowserLab& lab) { return lab.end(id); });
}
// `bytes`: the file, a Uint8Array (embind copies it into the string).
std::string estimate(const std::string& name, const std::string& bytes, const std::string& spacing,
                     bool has_spacing, const std::string& h_c, bool has_h_c) {
  return answered([&](BrowserLab& lab) {
    return lab.estimate(name, bytes, given(spacing, has_spacing), given(h_c, has_h_c));
  });
}

std::string rig() {
  return answered([](BrowserLab& lab) { return lab.rig(); });
}
std::string rig_open(const std::string& port, int baud) {
  return answered([&](BrowserLab& lab) { return lab.rig_open(port, baud); });
}
// `bytes`: what the port gave, a Uint8Array.
std::string rig_bytes(const std::string& bytes, bool ended) {
  return answered([&](BrowserLab& lab) { return lab.rig_bytes(bytes, ended); });
}
std::string rig_close() {
  return answered([](BrowserLab& lab) { return lab.rig_close(); });
}
std::string rig_log() {
  return answered([](BrowserLab& lab) { return lab.rig_log(); });
}

// A video the page decoded (web/src/video_decoding.ts), given frame by frame before the lab reads
// the file: video_begin (with `failure`, why the page could not decode it: then no frames),
// video_frame for each frame, video_end under the file's name as the page sends it.
GivenVideo g_video;

void video_begin(const std::string& container, const std::string& codec, int width, int height,
                 double fps, double scale, const std::string& failure) {
  g_video = GivenVideo{container, codec, width, height, fps, scale, failure, {}};
}
// `levels`: the frame's grey levels, a Uint8Array of width x height.
void video_frame(double t_s, int width, int height, const std::string& levels) {
  g_video.frames.push_back(GrayFrame{width, height, t_s, {levels.begin(), levels.end()}});
}
std::string video_end(const std::string& name) {
  return answered([&](BrowserLab&) {
    try {
      give_video(serve::upload_name(name), std::move(g_video));
    } catch (const std::invalid_argument& e) {
      return Answer{400, serve::error_json(std::string("the page's frames: ") + e.what())};
    }
    return Answer{200, nlohmann::json::object()};
  });
}
void forget_videos() {
  forget_given_videos();
  g_video = GivenVideo{};
}
// The width the lab's tracker reads a video's frames at [pixels].
int tracked_width() {
  return kTrackedWidth;
}

}  // namespace
}  // namespace fl::browser

EMSCRIPTEN_BINDINGS(frictionlab) {
  using namespace fl::browser;
  emscripten::function("open_lab", &open_lab);
  emscripten::function("lab", &lab);
  emscripten::function("create_session", &create_session);
  emscripten::function("events", &events);
  emscripten::function("control", &control);
  emscripten::function("file", &file);
  emscripten::function("report", &report);
  emscripten::function("end", &end);
  emscripten::function("estimate", &estimate);
  emscripten::function("rig", &rig);
  emscripten::function("rig_open", &rig_open);
  emscripten::function("rig_bytes", &rig_bytes);
  emscripten::function("rig_close", &rig_close);
  emscripten::function("rig_log", &rig_log);
  emscripten::function("video_begin", &video_begin);
  emscripten::function("video_frame", &video_frame);
  emscripten::function("video_end", &video_end);
  emscripten::function("forget_videos", &forget_videos);
  emscripten::function("tracked_width", &tracked_width);
}
