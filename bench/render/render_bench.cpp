// How fast the render layer is on this machine: ms per frame of the demo scene (about 6k
// triangles) at 640x360 and 1280x720 with and without shadows and 4x MSAA, the H.264 encoder's
// frames per second at 720p, PNG frames, and render + encode in one thread against the two
// overlapped through the encoder thread. Wall-clock time throughout: llvmpipe renders on its
// own threads (LP_NUM_THREADS; unset means one per core).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "render/components.hpp"
#include "render/demo_scene.hpp"
#include "render/gl/renderer.hpp"
#include "render/sinks/png.hpp"
#include "render/sinks/video.hpp"

namespace {

using namespace fl::render;
using Clock = std::chrono::steady_clock;

// A context, a renderer and the demo scene, animated: frame i is 1/30 s after frame i-1.
struct Rig {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<Renderer> renderer;
  DemoScene scene = make_demo_scene();
  std::vector<MeshId> ids;

  Rig(int width, int height, int samples, bool shadows, int shadow_map = 2048) {
    GlContextOptions options;
    options.width = width;
    options.height = height;
    options.samples = samples;
    context = make_gl_context(options);
    RendererOptions renderer_options;
    renderer_options.shadows = shadows;
    renderer_options.shadow_map_size = shadow_map;
    renderer = std::make_unique<Renderer>(*context, renderer_options);
    for (const auto& mesh : scene.meshes) ids.push_back(renderer->upload(mesh));
  }

  ImageView frame(int i) {
    const double t = i / 30.0;
    scene.pose(0.03f * static_cast<float>(std::sin(2.0 * std::numbers::pi * t / 0.794)),
               static_cast<float>(2.0 * std::numbers::pi * 1600.0 / 60.0 * t));
    renderer->begin_frame(scene.camera, scene.light);
    for (const auto& instance : scene.instances)
      renderer->draw(ids[instance.mesh], instance.pose, instance.casts_shadow);
    Overlay& o = renderer->overlay();
    o.rect(Rect{0, 0, 400, 24}, Color{0, 0, 0, 0.6f});
    o.text("t = " + std::to_string(t) + " s", Eigen::Vector2f(6, 4), 15, Color{});
    return renderer->end_frame();
  }
};

// CPU seconds used by the whole process (every llvmpipe and encoder thread), which other work
// on the machine disturbs far less than wall time.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// x264 presets the benchmarks compare, by index.
constexpr const char* kPresets[] = {"veryfast", "superfast", "ultrafast"};

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("fl-render-bench-" + name)).string();
}

void BM_RenderFrame(benchmark::State& state) {
  const auto width = static_cast<int>(state.range(0));
  const auto height = static_cast<int>(state.range(1));
  const bool shadows = state.range(2) != 0;
  const auto samples = static_cast<int>(state.range(3));
  const auto shadow_map = static_cast<int>(state.range(4));
  Rig rig(width, height, samples, shadows, shadow_map);
  for (int i = 0; i < 3; ++i) rig.frame(i);  // llvmpipe compiles shaders on first use
  int i = 0;
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) benchmark::DoNotOptimize(rig.frame(i++).pixels);
  state.counters["cpu_ms"] =
      1000.0 * (process_cpu_seconds() - cpu_start) / static_cast<double>(state.iterations());
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(rig.scene.triangle_count());
}
BENCHMARK(BM_RenderFrame)
    ->ArgNames({"w", "h", "shadows", "samples", "map"})
    ->Args({640, 360, 1, 4, 2048})
    ->Args({1280, 720, 1, 4, 2048})
    ->Args({640, 360, 0, 1, 2048})
    ->Args({1280, 720, 0, 1, 2048})
    ->Args({1280, 720, 1, 1, 2048})
    ->Args({1280, 720, 0, 4, 2048})
    ->Args({1280, 720, 1, 4, 1024})
    ->Args({1920, 1080, 1, 4, 2048})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// 60 distinct rendered frames at a size, to feed encoders.
std::vector<Image> rendered_frames(int width, int height) {
  Rig rig(width, height, 4, true);
  std::vector<Image> frames;
  for (int i = 0; i < 60; ++i) frames.push_back(copy_image(rig.frame(i)));
  return frames;
}

void BM_EncodeMp4(benchmark::State& state) {
  const auto width = static_cast<int>(state.range(0));
  const auto height = static_cast<int>(state.range(1));
  if (!kHasVideo) return state.SkipWithError("built without FRICTIONLAB_WITH_VIDEO");
  const std::vector<Image> frames = rendered_frames(width, height);
  VideoOptions options;
  options.path = temp_file("encode.mp4");
  options.queue_frames = 0;  // the encoder alone, on this thread
  options.preset = kPresets[state.range(2)];
  auto sink = make_mp4_sink(options);
  std::size_t i = 0;
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) sink->write(frames[i++ % frames.size()].view());
  state.counters["cpu_ms"] =
      1000.0 * (process_cpu_seconds() - cpu_start) / static_cast<double>(state.iterations());
  // Frames x264 still holds (lookahead) are flushed outside the timing; over hundreds of frames
  // this changes the rate by a few per cent.
  sink->finish();
  std::filesystem::remove(options.path);
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EncodeMp4)
    ->ArgNames({"w", "h", "preset"})
    ->Args({640, 360, 0})
    ->Args({1280, 720, 0})
    ->Args({1280, 720, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

void BM_PngFrame(benchmark::State& state) {
  const std::vector<Image> frames = rendered_frames(1280, 720);
  std::size_t i = 0;
  std::size_t bytes = 0;
  for (auto _ : state) bytes += encode_png(frames[i++ % frames.size()].view()).size();
  state.counters["kB_per_frame"] =
      static_cast<double>(bytes) / 1000.0 / static_cast<double>(state.iterations());
}
BENCHMARK(BM_PngFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

// 60 frames of 720p written as PNG files: arg 0 on one thread behind the caller (the sink
// `--frames` used before), arg N on a pool of N encoder threads (0: one per core). Frames per
// second of wall time, the folder written and synced as `--frames` does.
void BM_PngSink720p(benchmark::State& state) {
  const std::vector<Image> frames = rendered_frames(1280, 720);
  const auto threads = static_cast<unsigned>(state.range(0));
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fl-bench-png-" + std::to_string(threads));
  constexpr int kFrames = 60;
  for (auto _ : state) {
    std::filesystem::remove_all(dir);
    PngSinkOptions options;
    options.directory = dir.string();
    std::unique_ptr<FrameSink> sink =
        threads == 0 ? std::make_unique<ThreadedSink>(make_png_sink(options), 4)
                     : make_png_pool_sink(options, threads);
    for (int i = 0; i < kFrames; ++i) sink->write(frames[i % frames.size()].view());
    sink->finish();
  }
  std::filesystem::remove_all(dir);
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(kFrames) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PngSink720p)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// A whole 720p video of 150 frames (5 s), render and encode: with queue 0 the encoder runs on
// the render thread (no overlap); with queue 8 it runs on its own thread. x264_threads 0 lets
// x264 choose (3 on 2 cores); preset 0 is veryfast (the default), 1 superfast. The time
// includes flushing the encoder and closing the file.
void BM_RenderAndEncode720p(benchmark::State& state) {
  if (!kHasVideo) return state.SkipWithError("built without FRICTIONLAB_WITH_VIDEO");
  const auto queue = static_cast<int>(state.range(0));
  const auto encoder_threads = static_cast<int>(state.range(1));
  constexpr int kFrames = 150;
  Rig rig(1280, 720, 4, true);
  for (int i = 0; i < 3; ++i) rig.frame(i);
  for (auto _ : state) {
    const auto start = Clock::now();
    const double cpu_start = process_cpu_seconds();
    VideoOptions options;
    options.path = temp_file("render-encode.mp4");
    options.queue_frames = queue;
    options.encoder_threads = encoder_threads;
    options.preset = kPresets[state.range(2)];
    auto sink = make_mp4_sink(options);
    // Time the render thread spends handing frames over (encoding them itself with queue 0;
    // copying them, or waiting for a free slot, with a queue) and finishing the file.
    double in_sink = 0.0;
    for (int i = 0; i < kFrames; ++i) {
      const ImageView frame = rig.frame(i);
      const auto hand_over = Clock::now();
      sink->write(frame);
      in_sink += std::chrono::duration<double>(Clock::now() - hand_over).count();
    }
    const auto drain = Clock::now();
    sink->finish();
    in_sink += std::chrono::duration<double>(Clock::now() - drain).count();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    state.counters["in_sink_ms"] = 1000.0 * in_sink / kFrames;
    state.SetIterationTime(seconds);
    state.counters["ms_per_frame"] = 1000.0 * seconds / kFrames;
    state.counters["fps"] = kFrames / seconds;
    state.counters["cpu_ms"] = 1000.0 * (process_cpu_seconds() - cpu_start) / kFrames;
    std::filesystem::remove(options.path);
  }
}
BENCHMARK(BM_RenderAndEncode720p)
    ->ArgNames({"queue", "x264_threads", "preset"})
    ->Args({0, 0, 0})
    ->Args({8, 0, 0})
    ->Args({8, 1, 0})
    ->Args({8, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
