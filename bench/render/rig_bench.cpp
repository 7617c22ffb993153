// How fast the paper's rig renders: ms per frame of scenes/paper-rig.yaml drawn by the rig
// renderer (LEGO frame, rollers, gears, plate) with the teaching overlay, as the video recorder
// draws it (back faces of the fixed camera left out), at 1280x720 and 640x360 with shadows and
// 4x MSAA (the video's settings) and without; and what H.264 encoding adds to 300 such frames.
// The rig moves as in a run: the plate oscillates (T = 0.794 s, 30 mm), the rollers turn at
// 1600 rpm and the gear train at its speeds, blurred as the video draws them.
//
//   rig_bench [--benchmark_filter=...]    (scene: <source>/scenes/paper-rig.yaml, loaded by the
//                                          render tests' fixture, tests/support/rig_fixture.hpp)
//   FRICTIONLAB_GL=egl rig_bench ...      the GL back end (osmesa, egl; default auto), named in
//                                          BM_RigFrame's label
//
// BM_RigFrame reports wall ms per frame, fps, the CPU time of all the process's threads per
// frame (llvmpipe renders on LP_NUM_THREADS threads; unset: one per core) and the triangles of
// the camera and the shadow pass. Args: w, h, shadows, samples (4 = 4x MSAA), overlay, the
// shadow map's size (the recorder uses 512 at 360p, 1024 at 720p).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "../../tests/support/rig_fixture.hpp"
#include "render/components.hpp"
#include "render/gl/renderer.hpp"
#include "render/rig/rig_camera.hpp"
#include "render/rig/rig_overlay.hpp"
#include "render/rig/rig_view.hpp"
#include "render/sinks/video.hpp"

namespace {

using namespace fl::render;

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The rig, its renderer and a synthetic run: T = 0.794 s, 30 mm, 1600 rpm, a Hall trace.
struct RigFrames {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<RigView> view;
  Camera camera;
  fl::VideoDesc video;
  std::vector<HallPoint> hall;
  std::vector<double> pulses;
  std::vector<Eigen::Vector2d> motion;  // (t, x) for the strip
  ForceScale force_scale;
  bool overlay = true;

  RigFrames(int width, int height, int samples, bool shadows, bool with_overlay,
            int shadow_map = 2048)
      : overlay(with_overlay) {
    video.width = width;
    video.height = height;
    GlContextOptions options;
    options.width = width;
    options.height = height;
    options.samples = samples;
    context = make_gl_context(options);
    RendererOptions renderer_options;
    renderer_options.shadows = shadows;
    renderer_options.shadow_map_size = shadow_map;
    renderer = std::make_unique<Renderer>(*context, renderer_options);
    RigModel model = fl::test::paper_rig_model(true);  // as the front camera's videos draw it
    camera = rig_camera(model, video);
    force_scale =
        fl::render::force_scale(camera, width, height, Eigen::Vector3f::Zero(), 0.089, 0.413);
    cull_back_faces(model, camera.position);  // as the video recorder does without an orbit
    view = std::make_unique<RigView>(*renderer, std::move(model));
  }

  // Frame i read back at once.
  ImageView frame(int i) {
    draw(i);
    return renderer->end_frame();
  }

  // Frame i drawn, its read-back left to the caller (end_frame, or submit_frame and take_frame).
  void draw(int i) {
    const double t = i / 30.0;
    const double w = 2.0 * std::numbers::pi / 0.794;
    RigPose pose = rest_pose(compile_rig(fl::test::paper_rig()));
    pose.plate_x = 0.03 * std::cos(w * t);
    const auto& shafts = view->model().shafts;
    for (std::size_t s = 0; s < pose.shaft_angles.size(); ++s) {
      // The paper's train: 200 rpm at the motor, doubled by each stage, 1600 rpm at the
      // rollers, 960 rpm at the 40-tooth idlers.
      const std::string& role = shafts[s].role;
      double speed = 167.55;
      if (role == "motor") speed = 20.94;
      if (role.rfind("stage shaft ", 0) == 0)
        speed = 20.94 * std::pow(2.0, std::stod(role.substr(12)));
      if (role.rfind("idler", 0) == 0) speed = 167.55 * 24.0 / 40.0;
      pose.shaft_speeds[s] = speed * (s % 2 == 0 ? 1.0 : -1.0);
      pose.shaft_angles[s] = pose.shaft_speeds[s] * t;
    }
    renderer->begin_frame(camera, rig_light());
    view->draw(pose, 0.25 / 30.0);
    if (overlay) {
      // 2.5 s of a 1 kHz Hall trace: a pulse each time the magnet passes the sensor.
      hall.clear();
      pulses.clear();
      for (int k = 0; k < 2500; ++k) {
        const double ts = t - 2.5 + k * 1e-3;
        const double x = 0.03 * std::cos(w * ts);
        hall.push_back({ts, 512.0 + 300.0 * std::exp(-std::pow((x - 0.03) / 0.006, 2.0))});
      }
      for (double p = std::floor(t / 0.794) * 0.794; p > t - 2.5; p -= 0.794) pulses.push_back(p);
      RigOverlayState state;
      state.heading = "LEGO blocks on PVC rollers  \xc2\xb7  l = 89 mm";
      state.t = t;
      state.motor_speed = 20.7;
      state.roller_speed = 165.6;
      state.hall = hall;
      state.hall_range = std::array<double, 2>{500.0, 830.0};
      state.pulses = pulses;
      state.estimator.pulses = 9;
      state.estimator.periods = 8;
      state.estimator.period = 0.794;
      state.estimator.period_std = 0.006;
      state.estimator.mu_k = 0.285;
      state.estimator.mu_k_err = 0.008;
      state.paper_period = fl::test::paper_rig().friction.paper_period;
      state.paper_mu_k = fl::test::paper_rig().friction.paper_mu_k;
      // The forces (the thin plate's load shift) and x(t) against the theory, as a video draws
      // them.
      const double x = 0.03 * std::cos(w * t);
      const double load = 0.413;  // N, the plate's weight
      PlateForces forces;
      for (int k = 0; k < 2; ++k) {
        const double side = k == 0 ? -1.0 : 1.0;
        const double normal = load * (0.5 - side * x / 0.089);
        forces.rollers[static_cast<std::size_t>(k)] =
            ContactForce{true, normal, -side * 0.29 * normal,
                         Eigen::Vector3f(static_cast<float>(side * 0.0445), -0.024f, 0.0f)};
      }
      forces.centre = Eigen::Vector3f(static_cast<float>(x), -0.024f, 0.0036f);
      draw_force_arrows(renderer->overlay(), overlay_scale(video.width, video.height),
                        force_arrows(camera, video.width, video.height, forces, force_scale));
      state.forces = forces;
      state.force_scale = force_scale;
      motion.clear();
      for (int k = 0; k < 2500; ++k) {
        const double ts = t - 2.5 + k * 1e-3;
        motion.emplace_back(ts, 0.03 * std::cos(w * ts));
      }
      MotionStripState strip;
      strip.t = t;
      strip.simulated = motion;
      strip.theory = fl::HarmonicMotion{0.03, 0.0, w};
      strip.theory_label = "theory: thick plate, \xce\xbc\xe2\x82\x96 = 0.29, T = 0.7766 s";
      strip.turning_points = pulses;
      state.motion = strip;
      draw_rig_overlay(renderer->overlay(), video.width, video.height, state);
    }
  }
};

void report(benchmark::State& state, double cpu, const FrameStats& stats, std::size_t frames) {
  const double n = static_cast<double>(frames);
  state.counters["fps"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
  state.counters["cpu_ms"] = 1e3 * cpu / n;
  state.counters["triangles"] = static_cast<double>(stats.triangles);
  state.counters["shadow_tris"] = static_cast<double>(stats.shadow_triangles);
}

// Args: width, height, shadows, samples, overlay, shadow map size.
void BM_RigFrame(benchmark::State& state) {
  if (!kHasRender || (!kHasOsmesa && !kHasEgl)) {
    state.SkipWithError("built without rendering or without a GL back end");
    return;
  }
  RigFrames rig(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                static_cast<int>(state.range(3)), state.range(2) != 0, state.range(4) != 0,
                static_cast<int>(state.range(5)));
  for (int i = 0; i < 3; ++i) rig.frame(i);  // shaders compiled
  int i = 0;
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) benchmark::DoNotOptimize(rig.frame(i++).pixels);
  report(state, process_cpu_seconds() - cpu0, rig.renderer->last_frame_stats(),
         static_cast<std::size_t>(i));
  // The back end ($FRICTIONLAB_GL, else auto) beside the numbers.
  state.SetLabel(std::string(rig.context->backend_name()));
}
BENCHMARK(BM_RigFrame)
    ->ArgNames({"w", "h", "shadows", "samples", "overlay", "map"})
    ->Args({1280, 720, 1, 4, 1, 2048})
    ->Args({640, 360, 1, 4, 1, 2048})
    ->Args({1280, 720, 1, 4, 1, 1024})
    ->Args({640, 360, 1, 4, 1, 1024})
    ->Args({640, 360, 1, 4, 1, 512})
    ->Args({640, 360, 0, 4, 1, 512})
    ->Args({640, 360, 1, 1, 1, 512})
    ->Args({640, 360, 1, 4, 0, 512})
    ->Args({1280, 720, 1, 4, 0, 2048})
    ->Args({1280, 720, 0, 4, 0, 2048})
    ->Args({1280, 720, 1, 1, 0, 2048})
    ->Args({1280, 720, 0, 1, 0, 2048})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

// A stream of frames read back behind the drawing, as videos take them (Renderer::submit_frame,
// then GlContext::take_frame once frames_behind() frames wait): on a GPU the copies of earlier
// frames overlap the drawing of later ones; OSMesa reads each frame where it is drawn. Compare
// with BM_RigFrame at the same arguments. Args: width, height.
void BM_RigFrameStream(benchmark::State& state) {
  if (!kHasRender || (!kHasOsmesa && !kHasEgl)) {
    state.SkipWithError("built without rendering or without a GL back end");
    return;
  }
  RigFrames rig(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 4, true, true,
                state.range(1) > 480 ? 1024 : 512);
  for (int i = 0; i < 3; ++i) rig.frame(i);  // shaders compiled
  GlContext& gl = *rig.context;
  int i = 0;
  std::uint64_t checksum = 0;
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    rig.draw(i++);
    rig.renderer->submit_frame();
    while (gl.queued_frames() > gl.frames_behind()) checksum += gl.take_frame().row(0)[0];
  }
  while (gl.queued_frames() > 0) checksum += gl.take_frame().row(0)[0];
  benchmark::DoNotOptimize(checksum);
  report(state, process_cpu_seconds() - cpu0, rig.renderer->last_frame_stats(),
         static_cast<std::size_t>(i));
  state.SetLabel(std::string(rig.context->backend_name()) + ", " +
                 std::to_string(gl.frames_behind()) + " frames behind");
}
BENCHMARK(BM_RigFrameStream)
    ->ArgNames({"w", "h"})
    ->Args({1280, 720})
    ->Args({1920, 1080})
    ->Args({3840, 2160})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

// What encoding adds: the same 300 frames (10 s of video at 30 fps) rendered alone, then
// rendered and handed to the H.264 encoder (its own thread, queue of 8), from the first frame to
// the closed file. Reports both in ms per frame and the overhead in %. Args: width, height, x264
// threads (0: x264 decides).
void BM_RigFrameEncoded(benchmark::State& state) {
  if (!kHasRender || (!kHasOsmesa && !kHasEgl) || !kHasVideo) {
    state.SkipWithError("built without rendering, a GL back end or video");
    return;
  }
  const int width = static_cast<int>(state.range(0));
  const int height = static_cast<int>(state.range(1));
  RigFrames rig(width, height, 4, true, true, height > 480 ? 1024 : 512);
  for (int i = 0; i < 3; ++i) rig.frame(i);
  const std::string path = (std::filesystem::temp_directory_path() / "fl-rig-bench.mp4").string();
  constexpr int kFrames = 300;
  using Clock = std::chrono::steady_clock;
  double alone = 0.0, encoded = 0.0, cpu = 0.0;
  for (auto _ : state) {
    auto start = Clock::now();
    for (int i = 0; i < kFrames; ++i) benchmark::DoNotOptimize(rig.frame(i).pixels);
    alone += std::chrono::duration<double>(Clock::now() - start).count();
    const double cpu0 = process_cpu_seconds();
    start = Clock::now();
    VideoOptions options;
    options.path = path;
    options.encoder_threads = static_cast<int>(state.range(2));
    auto sink = make_mp4_sink(options);
    for (int i = 0; i < kFrames; ++i) sink->write(rig.frame(i));
    sink->finish();
    encoded += std::chrono::duration<double>(Clock::now() - start).count();
    cpu += process_cpu_seconds() - cpu0;
  }
  const double frames = static_cast<double>(state.iterations()) * kFrames;
  state.counters["render_ms"] = 1e3 * alone / frames;
  state.counters["encoded_ms"] = 1e3 * encoded / frames;
  state.counters["overhead_pct"] = 100.0 * (encoded / alone - 1.0);
  state.counters["cpu_ms"] = 1e3 * cpu / frames;
  std::filesystem::remove(path);
}
BENCHMARK(BM_RigFrameEncoded)
    ->ArgNames({"w", "h", "x264_threads"})
    ->Args({1280, 720, 0})
    ->Args({640, 360, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
