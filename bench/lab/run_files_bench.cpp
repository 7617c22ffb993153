// What a run's files cost: the minimal scene run through the request every front end asks
// (prepare_run, execute_run), with and without `out` (summary.json, trajectory.csv, hall.csv,
// periods.csv, cycles.csv, timing.json, streamed to the disk as the run goes). Reports the wall
// time and the growth of the process's resident memory over the run (sampled every 1000 steps
// through the run's progress), for 153 s and 600 s of simulated time. Targets: the 153 s run's
// files cost at most 1.5x the run without them; a 600 s run with every output under 40 MiB.
// Run: build/.../bench/lab/bench_run_files [--benchmark_repetitions=3]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>

#include "lab/request/run_request.hpp"

namespace {

// The process's resident memory [bytes], from /proc/self/statm.
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

void BM_MinimalRun(benchmark::State& state) {
  const bool files = state.range(0) != 0;
  const long long seconds = state.range(1);
  const std::string out = std::string(FRICTIONLAB_BENCH_BINARY_DIR) + "/bench-run-files";
  double growth = 0.0;
  for (auto _ : state) {
    std::filesystem::remove_all(out);
    fl::RunRequest r;
    r.scene.file = std::string(FRICTIONLAB_BENCH_SOURCE_DIR) + "/scenes/minimal.yaml";
    r.scene.asset_dir = FRICTIONLAB_BENCH_ASSET_DIR;
    r.duration = fl::QuantityInput{std::to_string(seconds) + " s"};
    if (files) r.out = out;
    const double before = resident_bytes();
    double peak = before;
    fl::RunControl control;
    control.progress = [&peak](double) { peak = std::max(peak, resident_bytes()); };
    const auto start = std::chrono::steady_clock::now();
    const fl::PreparedRun prepared = fl::prepare_run(r);
    const fl::RunResult result = fl::execute_run(prepared, control);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    peak = std::max(peak, resident_bytes());
    growth = std::max(growth, peak - before);
    benchmark::DoNotOptimize(result.summary.steps);
    state.SetIterationTime(wall);
  }
  state.counters["resident_growth_MiB"] = growth / (1 << 20);
  state.SetLabel(std::string(files ? "with every file" : "no files") + ", " +
                 std::to_string(seconds) + " s simulated");
}

BENCHMARK(BM_MinimalRun)
    ->Args({0, 153})
    ->Args({1, 153})
    ->Args({1, 600})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
