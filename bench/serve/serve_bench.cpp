// What one browser session costs the server: a second of simulated time played at real time, as
// the stream does it (30 ticks, each stepping the live run and writing its `state` event's JSON).
// The CPU time per iteration is the share of one core a session takes at real time (target: under
// 2 % on the 2-core machine). Run: build/.../bench/serve/bench_serve
#include <chrono>
#include <string>

#include <benchmark/benchmark.h>

#include "lab/request/session_request.hpp"
#include "serve/lab_session.hpp"

namespace {

void BM_SessionSecondAtRealTime(benchmark::State& state, const std::string& scene) {
  const std::string scenes = std::string(FRICTIONLAB_BENCH_SOURCE_DIR) + "/scenes";
  // A long run, so that no iteration reaches its end.
  const fl::PreparedSession prepared =
      fl::prepare_session({scene, {"world.duration=1000s"}}, scenes, FRICTIONLAB_BENCH_ASSET_DIR);
  fl::serve::LabSession session(scene, prepared);
  auto now = fl::serve::Clock::now();
  session.play(now);
  std::size_t bytes = 0;
  for (auto _ : state) {
    for (int tick = 0; tick < 30; ++tick) {
      now += std::chrono::microseconds(33334);
      if (const auto said = session.tick(now).state) bytes += said->dump().size();
    }
  }
  // 100 x the CPU seconds per simulated second: a rate's inverse of iterations / 100.
  state.counters["core_pct_at_real_time"] =
      benchmark::Counter(static_cast<double>(state.iterations()) / 100.0,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["event_bytes"] =
      static_cast<double>(bytes) / (30.0 * static_cast<double>(state.iterations()));
}

BENCHMARK_CAPTURE(BM_SessionSecondAtRealTime, minimal, std::string("minimal"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SessionSecondAtRealTime, paper_rig, std::string("paper-rig"))
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
