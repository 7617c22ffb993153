// A phone's video tracked (tracking/track_video.hpp): the plate followed in a 1080p 60 fps H.264
// video (10 s of the synthetic plate of tests/support/synthetic_plate_video.hpp, encoded once by
// libx264's medium preset, the High profile a phone writes, and kept in the temporary folder),
// decoding included. Counters: the video's seconds per second of wall time (real_time_x: the
// target is 2 or more on 2 cores), frames per second, and the process's peak resident memory
// during the tracking (peak_MB; the counter resets it first). FRICTIONLAB_BENCH_VIDEO=FILE tracks
// that file instead (BM_TrackGivenVideo): how the 10-minute 4K figure is measured.
// Run: build/.../bench/tracking/bench_tracking [--benchmark_filter=...]
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>

#include "support/filmed_plate.hpp"
#include "tracking/track_video.hpp"
#include "tracking/video_decoder_module.hpp"

namespace {

// The peak resident memory since the last reset [MB], from /proc/self/status (VmHWM).
double peak_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0.0;
      status >> kb;
      return kb / 1024.0;
    }
  }
  return 0.0;
}

void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

// The 1080p 60 fps video, made once.
std::string phone_video() {
  const auto path = std::filesystem::temp_directory_path() / "frictionlab-bench-1080p60.mp4";
  if (std::filesystem::exists(path)) return path.string();
  fl::test::PlateScene scene;
  scene.width = 1920;
  scene.height = 1080;
  scene.centre_x = 960.0;
  scene.centre_y = 540.0;
  scene.plate_length_px = 900.0;
  scene.plate_height_px = 80.0;
  scene.amplitude_px = 160.0;
  fl::test::film_plate(scene, 10.0, 60, path.string(), "medium");
  return path.string();
}

void track(benchmark::State& state, const std::string& path) {
  setenv(fl::kVideoDecoderVariable, FRICTIONLAB_BENCH_DECODER_MODULE, 0);
  double video_seconds = 0.0, wall_seconds = 0.0, frames = 0.0, peak = 0.0;
  for (auto _ : state) {
    reset_peak();
    const auto start = std::chrono::steady_clock::now();
    const fl::VideoTrack t = fl::track_plate_in_video(path, fl::TrackOptions{});
    wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    frames += t.video.frames_read;
    video_seconds += t.track.t_s.back() + (t.video.fps > 0 ? 1.0 / t.video.fps : 0.0);
    peak = std::max(peak, peak_mb());
    benchmark::DoNotOptimize(t.track.x.data());
  }
  state.counters["real_time_x"] = video_seconds / wall_seconds;
  state.counters["frames_per_s"] = frames / wall_seconds;
  state.counters["peak_MB"] = peak;
}

void BM_Track1080p60(benchmark::State& state) {
  track(state, phone_video());
}
BENCHMARK(BM_Track1080p60)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_TrackGivenVideo(benchmark::State& state) {
  const char* given = std::getenv("FRICTIONLAB_BENCH_VIDEO");
  if (given == nullptr || *given == '\0') {
    state.SkipWithError("set FRICTIONLAB_BENCH_VIDEO to a video file");
    return;
  }
  track(state, given);
}
BENCHMARK(BM_TrackGivenVideo)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
