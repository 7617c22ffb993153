// Renders the demo scene with a teaching-video overlay (title, time, a scrolling trace with
// markers, values) to a still PNG, and optionally to an MP4 of a few seconds, timing each stage.
// Not a test: a way to look at the render layer's output and time a whole video end to end.
//
//   render_demo [--size 1280x720] [--png out.png] [--mp4 out.mp4] [--seconds 10] [--fps 30]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "render/demo_scene.hpp"
#include "render/gl/renderer.hpp"
#include "render/sinks/png.hpp"
#include "render/sinks/video.hpp"

namespace {

using fl::render::Color;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The overlay a teaching video carries, with made-up numbers (the estimator is not wired yet).
void draw_overlay(fl::render::Overlay& o, int width, int height, double t) {
  const float w = static_cast<float>(width);
  const float h = static_cast<float>(height);
  const float s = h / 360.0f;  // sizes are given for 640x360 and scale with the frame
  const Color panel{0.05f, 0.07f, 0.10f, 0.72f};
  const Color white{1.0f, 1.0f, 1.0f};
  const Color soft{0.80f, 0.85f, 0.92f};
  o.rect(fl::render::Rect{0, 0, w, 24 * s}, panel);
  o.text("Friction oscillator: oak on PVC rollers, l = 89 mm", Eigen::Vector2f(8 * s, 4 * s),
         15 * s, white);
  char line[128];
  std::snprintf(line, sizeof line, "t = %.2f s   (x0.25 slow motion)", t);
  o.text(line, Eigen::Vector2f(w - 8 * s, 4 * s), 15 * s, soft, fl::render::TextAlign::kRight);

  // A scrolling Hall trace: the last 2 s, pulses marked where the plate passes the sensor.
  const fl::render::Rect plot{8 * s, h - 98 * s, 300 * s, 90 * s};
  o.rect(plot, panel);
  o.rect_outline(plot, 1.0f, Color{1, 1, 1, 0.35f});
  std::vector<Eigen::Vector2f> trace;
  const double window = 2.0;
  const double period = 0.794;
  for (int i = 0; i <= 200; ++i) {
    const double ts = t - window + window * i / 200.0;
    const double x = std::sin(2.0 * std::numbers::pi * ts / period);
    const double signal = std::exp(-std::pow((x - 0.9) / 0.08, 2.0));
    trace.emplace_back(plot.x + plot.width * static_cast<float>(i) / 200.0f,
                       plot.y + plot.height - 12 * s - static_cast<float>(signal) * 60 * s);
  }
  o.polyline(trace, 1.6f * s, Color{1.0f, 0.78f, 0.15f});
  for (int k = -4; k <= 4; ++k) {
    const double pulse = period * (std::floor(t / period) + k) + period / 4.0;
    if (pulse < t - window || pulse > t) continue;
    const float x = plot.x + plot.width * static_cast<float>((pulse - (t - window)) / window);
    o.dot(Eigen::Vector2f(x, plot.y + plot.height - 72 * s), 3.5f * s, Color{0.3f, 0.9f, 0.4f});
  }
  o.text("Hall sensor (last 2 s)", Eigen::Vector2f(plot.x + 6 * s, plot.y + 4 * s), 12 * s, soft);

  const fl::render::Rect values{w - 268 * s, h - 64 * s, 260 * s, 56 * s};
  o.rect(values, panel);
  o.text("T = 0.794 ± 0.006 s", Eigen::Vector2f(values.x + 8 * s, values.y + 6 * s), 16 * s, white);
  o.text("μₖ = 0.285 ± 0.008   (paper: 0.29 ± 0.01)",
         Eigen::Vector2f(values.x + 8 * s, values.y + 30 * s), 12.5f * s, soft);
}

}  // namespace

int main(int argc, char** argv) {
  int width = 1280;
  int height = 720;
  std::string png = "render_demo.png";
  std::string mp4;
  double seconds = 10.0;
  int fps = 30;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--size" && std::sscanf(value.c_str(), "%dx%d", &width, &height) == 2) continue;
    if (key == "--png") {
      png = value;
    } else if (key == "--mp4") {
      mp4 = value;
    } else if (key == "--seconds") {
      seconds = std::stod(value);
    } else if (key == "--fps") {
      fps = std::stoi(value);
    } else {
      std::fprintf(stderr, "render_demo: unknown option %s\n", key.c_str());
      return 2;
    }
  }
  try {
    const auto start = Clock::now();
    fl::render::GlContextOptions options;
    options.width = width;
    options.height = height;
    const auto context = fl::render::make_gl_context(options);
    fl::render::Renderer renderer(*context);
    fl::render::DemoScene scene = fl::render::make_demo_scene();
    std::vector<fl::render::MeshId> ids;
    for (const auto& mesh : scene.meshes) ids.push_back(renderer.upload(mesh));
    std::printf("%s, %dx%d, %zu triangles, set up in %.3f s\n", context->description().c_str(),
                width, height, scene.triangle_count(), seconds_since(start));

    // The plate oscillates with T = 0.794 s and 30 mm amplitude; rollers at 1600 rpm; the video
    // runs at 0.25x.
    const auto frame_at = [&](double t) {
      scene.pose(0.03f * static_cast<float>(std::sin(2.0 * std::numbers::pi * t / 0.794)),
                 static_cast<float>(1600.0 / 60.0 * 2.0 * std::numbers::pi * t));
      renderer.begin_frame(scene.camera, scene.light);
      for (const auto& instance : scene.instances)
        renderer.draw(ids[instance.mesh], instance.pose, instance.casts_shadow);
      draw_overlay(renderer.overlay(), width, height, t);
      return renderer.end_frame();
    };

    const auto still = Clock::now();
    fl::render::write_png(png, frame_at(1.0));
    std::printf("still %s in %.3f s (first frame, shaders compiled)\n", png.c_str(),
                seconds_since(still));

    if (!mp4.empty()) {
      const auto video_start = Clock::now();
      fl::render::VideoOptions video;
      video.path = mp4;
      video.fps = fps;
      auto sink = fl::render::make_mp4_sink(video);
      const int frames = static_cast<int>(std::lround(seconds * fps));
      double render_seconds = 0.0;
      for (int i = 0; i < frames; ++i) {
        const auto r = Clock::now();
        const fl::render::ImageView frame = frame_at(0.25 * i / fps);
        render_seconds += seconds_since(r);
        sink->write(frame);
      }
      sink->finish();
      const double total = seconds_since(video_start);
      std::printf(
          "video %s: %d frames (%.1f s at %d fps) in %.2f s wall; rendering %.2f s "
          "(%.1f ms a frame); %.1f fps end to end\n",
          mp4.c_str(), frames, seconds, fps, total, render_seconds,
          1000.0 * render_seconds / frames, frames / total);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_demo: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
