#include "scene/video_yaml.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "core/units.hpp"
#include "io/yaml_node.hpp"

namespace fl {
namespace {

std::array<double, 3> read_point(const YamlNode& node) {
  if (node.size() != 3) node.fail("expected a list of 3 lengths [x, y, z]");
  return {node[0].quantity(Dimension::kLength), node[1].quantity(Dimension::kLength),
          node[2].quantity(Dimension::kLength)};
}

void fail_if(const YamlNode& node, const std::string& problem) {
  if (!problem.empty()) node.fail(problem);
}

int read_whole(const YamlNode& node) {
  const std::int64_t value = node.integer();
  if (value < 0 || value > 100000) node.fail("expected a whole number of pixels or frames");
  return static_cast<int>(value);
}

}  // namespace

std::optional<std::array<int, 2>> parse_video_size(std::string_view text) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos || x == 0 || x + 1 >= text.size()) return std::nullopt;
  std::array<int, 2> size{};
  const std::string_view parts[2] = {text.substr(0, x), text.substr(x + 1)};
  for (int i = 0; i < 2; ++i) {
    const std::string_view p = parts[i];
    const auto [end, error] = std::from_chars(p.data(), p.data() + p.size(), size[i]);
    if (error != std::errc{} || end != p.data() + p.size()) return std::nullopt;
  }
  return size;
}

std::string video_size_problem(int width, int height) {
  if (width < 16 || height < 16 || width > 7680 || height > 4320)
    return "a frame of " + std::to_string(width) + "x" + std::to_string(height) +
           " pixels is out of range (16x16 to 7680x4320)";
  if (width % 2 != 0 || height % 2 != 0)
    return "H.264 in yuv420p needs an even width and height, found " + std::to_string(width) + "x" +
           std::to_string(height);
  return {};
}

std::string video_fps_problem(int fps) {
  if (fps < 1 || fps > 240)
    return "expected 1 to 240 frames per second, found " + std::to_string(fps);
  return {};
}

std::string video_slow_motion_problem(double factor) {
  if (!std::isfinite(factor) || factor < 0.01 || factor > 1000.0)
    return "expected a slow-motion factor from 0.01 to 1000 (1: real time, 4: four times "
           "slower)";
  return {};
}

std::string video_camera_problem(std::string_view preset) {
  for (const std::string_view name : kCameraPresets)
    if (preset == name) return {};
  return "expected a camera preset (front, top, sensor, phone) or {position, target, fov}, found "
         "\"" +
         std::string(preset) + "\"";
}

std::string video_orbit_problem(double rad_per_second) {
  if (!std::isfinite(rad_per_second) || std::fabs(rad_per_second) > 2.0 * kPi)
    return "expected an orbit of at most 360 deg/s (e.g. \"10 deg/s\")";
  return {};
}

VideoDesc read_video(const YamlNode& node) {
  node.expect_map();
  node.allow_keys({"size", "fps", "slow_motion", "camera", "orbit", "title", "end_card",
                   "phase_portrait", "captions"});
  VideoDesc v;
  if (auto size = node.find("size")) {
    if (size->is_sequence()) {
      if (size->size() != 2) size->fail("expected [width, height] in pixels or \"1280x720\"");
      v.width = read_whole((*size)[0]);
      v.height = read_whole((*size)[1]);
    } else {
      const auto parsed = parse_video_size(size->text());
      if (!parsed)
        size->fail("expected a frame size like \"1280x720\" or [1280, 720], found \"" +
                   size->text() + "\"");
      v.width = (*parsed)[0];
      v.height = (*parsed)[1];
    }
    fail_if(*size, video_size_problem(v.width, v.height));
  }
  if (auto fps = node.find("fps")) {
    v.fps = read_whole(*fps);
    fail_if(*fps, video_fps_problem(v.fps));
  }
  if (auto slow = node.find("slow_motion")) {
    v.slow_motion = slow->number();
    fail_if(*slow, video_slow_motion_problem(v.slow_motion));
  }
  if (auto camera = node.find("camera")) {
    if (camera->is_map()) {
      camera->allow_keys({"position", "target", "fov"});
      VideoCameraPlacement placed;
      placed.position = read_point(camera->at("position"));
      placed.target = read_point(camera->at("target"));
      if (auto fov = camera->find("fov")) {
        placed.fov = fov->quantity(Dimension::kAngle);
        const double degrees = placed.fov * 180.0 / kPi;
        if (!(degrees >= 5.0 && degrees <= 120.0))
          fov->fail("expected a vertical field of view from 5 deg to 120 deg");
      }
      double distance = 0.0;
      for (int i = 0; i < 3; ++i)
        distance += std::pow(placed.position[static_cast<std::size_t>(i)] -
                                 placed.target[static_cast<std::size_t>(i)],
                             2.0);
      if (std::sqrt(distance) < 1e-3)
        camera->at("target").fail("the camera's target must lie away from its position");
      v.placed = placed;
      v.camera.clear();
    } else {
      v.camera = camera->text();
      fail_if(*camera, video_camera_problem(v.camera));
    }
  }
  if (auto orbit = node.find("orbit")) {
    v.orbit = orbit->quantity(Dimension::kAngularSpeed);
    fail_if(*orbit, video_orbit_problem(v.orbit));
  }
  if (auto title = node.find("title")) v.title = title->boolean();
  if (auto end_card = node.find("end_card")) v.end_card = end_card->boolean();
  if (auto phase = node.find("phase_portrait")) v.phase_portrait = phase->boolean();
  if (auto captions = node.find("captions")) v.captions = read_captions(*captions);
  return v;
}

}  // namespace fl
