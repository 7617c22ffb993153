// Physics steps per second of the minimal scene on one core (target: >= 200 000), and the
// cost of one simulated second at the default step.
#include <benchmark/benchmark.h>

#include "physics/rig_world.hpp"

namespace {

fl::Scene minimal_scene() {
  fl::Scene s;  // the defaults are the minimal scene's plate, rollers and release
  s.friction.mu_k = 0.29;
  return s;
}

// Steps a world of the scene for as long as the benchmark asks, counting steps per second.
void step_world(benchmark::State& state, const fl::Scene& scene) {
  fl::RigWorld world(scene);
  for (auto _ : state) {
    world.step();
    benchmark::DoNotOptimize(world.plate().x);
  }
  state.counters["steps_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_MinimalSceneStep(benchmark::State& state) {
  step_world(state, minimal_scene());
}
BENCHMARK(BM_MinimalSceneStep);

// The same with a slip-dependent law (Stribeck drop and slope): the law's coefficient is computed
// per contact point and step at the mid-step slip (target: at most 15 % below the coulomb step).
void BM_MinimalSceneStepStribeck(benchmark::State& state) {
  fl::Scene scene = minimal_scene();
  scene.friction.law = fl::FrictionLawKind::kStribeck;
  scene.friction.mu_s = 0.35;
  scene.friction.v_s = 1e-3;
  scene.friction.beta = -0.001;
  step_world(state, scene);
}
BENCHMARK(BM_MinimalSceneStepStribeck);

// Ten simulated seconds at 1 kHz, world construction included (target: under 0.05 s).
void BM_MinimalSceneTenSecondsAt1kHz(benchmark::State& state) {
  fl::Scene scene = minimal_scene();
  scene.world.time_step = 1e-3;
  for (auto _ : state) {
    fl::RigWorld world(scene);
    for (int i = 0; i < 10000; ++i) world.step();
    benchmark::DoNotOptimize(world.plate().x);
  }
}
BENCHMARK(BM_MinimalSceneTenSecondsAt1kHz)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
