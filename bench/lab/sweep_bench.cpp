// Throughput of frictionlab sweep: scenes/sweeps/spacing.yaml (3 materials x 40 spacings x 20
// simulated seconds, 120 points) run whole, into a fresh folder, on 1 and on 2 worker threads.
// Reports the wall time, points per second, and for 2 workers the speed-up over 1 and the
// parallel efficiency (speed-up / workers). Targets: under 20 s on a 2-core machine,
// efficiency at least 85 %.
//
// And a sweep at a stated accuracy: scenes/sweeps/materials-spacings.yaml (9 Table I materials x
// 1112 spacings x 20 simulated seconds, 10 008 points at 0.01 %, the trajectory's period only) on
// every core. Reports the wall time, points per second, the mean step count, and the largest
// |T / T_thick - 1| over the points (the accuracy the sweep promised). Target: under 60 s on the
// 2-core machine, every point within 0.01 %.
// Run: build/.../bench/lab/bench_sweep [--benchmark_filter=Accuracy] [--benchmark_repetitions=3]
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "io/paper_table_yaml.hpp"
#include "lab/sweep/sweep_run.hpp"

namespace {

const fl::PaperTable& table() {
  static const fl::PaperTable t =
      fl::load_paper_table(fl::paper_table_path(FRICTIONLAB_BENCH_ASSET_DIR));
  return t;
}

// The fastest wall time seen per worker count, for the speed-up.
std::map<int, double>& best_wall() {
  static std::map<int, double> best;
  return best;
}

// Runs the repository's sweep file `name` whole, into a fresh folder `dir`, on `workers` threads
// (0: every core), once per iteration; the last run's outcome.
fl::SweepOutcome run_whole(benchmark::State& state, const std::string& name,
                           const std::filesystem::path& dir, int workers) {
  const fl::SceneInputs inputs{[]() -> const fl::PaperTable& { return table(); }, {}};
  const fl::SweepSpec spec = fl::load_sweep_file(
      std::string(FRICTIONLAB_BENCH_SOURCE_DIR) + "/scenes/sweeps/" + name, inputs);
  fl::SweepOutcome outcome;
  for (auto _ : state) {
    fl::SweepRunOptions options;
    options.out_dir = dir.string();
    options.workers = workers;
    options.fresh = true;
    options.inputs = inputs;
    outcome = fl::run_sweep(spec, options);
    state.SetIterationTime(outcome.wall_s);
    if (!outcome.complete || outcome.ran != spec.point_count())
      state.SkipWithError("the sweep did not run every point");
  }
  return outcome;
}

void BM_SpacingSweep(benchmark::State& state) {
  const int workers = static_cast<int>(state.range(0));
  const std::filesystem::path dir =
      std::filesystem::path(FRICTIONLAB_BENCH_BINARY_DIR) / "bench-sweep" / std::to_string(workers);
  const fl::SweepOutcome outcome = run_whole(state, "spacing.yaml", dir, workers);
  double& best = best_wall()[workers];
  if (best == 0.0 || outcome.wall_s < best) best = outcome.wall_s;
  state.counters["points"] = static_cast<double>(outcome.ran);
  state.counters["points_per_s"] = static_cast<double>(outcome.ran) / outcome.wall_s;
  state.counters["sim_s_per_wall_s"] = 20.0 * static_cast<double>(outcome.ran) / outcome.wall_s;
  if (workers > 1 && best_wall().contains(1)) {
    const double speedup = best_wall()[1] / best;
    state.counters["speedup"] = speedup;
    state.counters["efficiency"] = speedup / workers;
  }
}
BENCHMARK(BM_SpacingSweep)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);

void BM_AccuracySweep(benchmark::State& state) {
  const std::filesystem::path dir =
      std::filesystem::path(FRICTIONLAB_BENCH_BINARY_DIR) / "bench-sweep" / "accuracy";
  const fl::SweepOutcome outcome = run_whole(state, "materials-spacings.yaml", dir, 0);
  double worst = 0.0, steps = 0.0;
  int ok = 0;
  for (const auto& [index, point] : fl::SweepStore::open(dir.string()).load_points()) {
    const nlohmann::json& row = point.row;
    if (row["status"] != "ok" || !row["period_trajectory_s"].is_number()) continue;
    ++ok;
    steps += row["steps"].get<double>();
    worst = std::max(worst, std::fabs(row["period_trajectory_s"].get<double>() /
                                          row["period_thick_s"].get<double>() -
                                      1.0));
  }
  state.counters["points"] = static_cast<double>(outcome.ran);
  state.counters["points_per_s"] = static_cast<double>(outcome.ran) / outcome.wall_s;
  state.counters["workers"] = outcome.workers;
  state.counters["ok"] = ok;
  state.counters["mean_steps"] = ok > 0 ? steps / ok : 0.0;
  state.counters["worst_error"] = worst;
}
BENCHMARK(BM_AccuracySweep)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
