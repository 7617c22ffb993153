// The paper's rig, whole: real-time factor of a 10 s run (frame, guides, motor and gear train,
// Hall sensor and estimator; target: 20 x real time or faster), the same with two phones
// recording, and loading a scene of 300
// LEGO frame parts (target: under 0.5 s, meshes not needed by the physics).
#include <string>

#include <benchmark/benchmark.h>

#include "assets/part_catalog.hpp"
#include "core/paper_table.hpp"
#include "io/paper_table_yaml.hpp"
#include "lab/run/experiment.hpp"
#include "scene/scene_yaml.hpp"

namespace {

const fl::PaperTable& table() {
  static const fl::PaperTable t = fl::load_paper_table(fl::paper_table_path(FRICTIONLAB_ASSET_DIR));
  return t;
}

fl::Scene paper_rig() {
  const fl::assets::PartCatalog parts =
      fl::assets::load_part_catalog(fl::assets::part_catalog_path(FRICTIONLAB_ASSET_DIR));
  return fl::load_scene_file(
      std::string(FRICTIONLAB_SOURCE_DIR) + "/scenes/paper-rig.yaml", {},
      []() -> const fl::PaperTable& { return table(); },
      [&parts]() -> const fl::assets::PartCatalog& { return parts; });
}

void BM_PaperRigTenSeconds(benchmark::State& state) {
  const fl::Scene scene = paper_rig();
  double simulated = 0.0;
  for (auto _ : state) {
    const fl::RunSummary r = fl::run_experiment(scene, {});
    simulated += r.duration;
    benchmark::DoNotOptimize(r.period_trajectory);
  }
  state.counters["real_time_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PaperRigTenSeconds)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same run with a phone's magnetometer beside the rig (100 Hz) and its accelerometer on the
// plate (400 Hz), their samples kept: what the phones cost beside the Hall sensor's 1 kHz.
void BM_PaperRigWithPhonesTenSeconds(benchmark::State& state) {
  fl::Scene scene = paper_rig();
  fl::PhoneDesc beside;
  beside.position = {0.114, 0.060, -0.050};
  fl::PhoneDesc on_plate = fl::phone_with(fl::PhoneSensor::kAccelerometer);
  on_plate.height = 0.0096;
  scene.phones = {beside, on_plate};
  fl::RunOptions options;
  options.record_phones = true;
  double simulated = 0.0;
  for (auto _ : state) {
    fl::RunRecording recording;
    const fl::RunSummary r = fl::run_experiment(scene, options, &recording);
    simulated += r.duration;
    benchmark::DoNotOptimize(recording.phones.data());
  }
  state.counters["real_time_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PaperRigWithPhonesTenSeconds)->Unit(benchmark::kMillisecond)->UseRealTime();

// A whole run of the minimal scene (10 s at 1 ms, no sensor): the world's steps with what the run
// does at each (the regime monitor, the solver's convergence check, the trajectory's tracker).
void BM_MinimalSceneRunTenSeconds(benchmark::State& state) {
  fl::Scene scene;
  scene.friction.mu_k = 0.29;
  long long steps = 0;
  for (auto _ : state) {
    const fl::RunSummary r = fl::run_experiment(scene, {});
    steps += r.steps;
    benchmark::DoNotOptimize(r.period_trajectory);
  }
  state.counters["steps_per_second"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MinimalSceneRunTenSeconds)->Unit(benchmark::kMillisecond)->UseRealTime();

// A frame of 300 parts, loaded from YAML text with the part index read from its file each time
// (the cost a user pays when a scene opens).
void BM_LoadSceneWith300Parts(benchmark::State& state) {
  std::string text = "format: 1\nfriction: {mu_k: 0.3}\nframe:\n  parts:\n";
  const char* parts[] = {"brick-2x4", "brick-2x2", "technic-brick-1x16", "brick-1x2", "plate-2x8"};
  for (int i = 0; i < 300; ++i) {
    text += "    - {part: " + std::string(parts[i % 5]) + ", at: [" + std::to_string(i % 20 - 10) +
            ", " + std::to_string(8 + i / 20) + ", " + std::to_string(3 * (i % 7)) +
            "], guide: " + (i % 3 == 0 ? "true" : "false") + "}\n";
  }
  for (auto _ : state) {
    const fl::assets::PartCatalog catalog =
        fl::assets::load_part_catalog(fl::assets::part_catalog_path(FRICTIONLAB_ASSET_DIR));
    const fl::Scene scene = fl::load_scene_text(
        text, "300-parts.yaml", {}, []() -> const fl::PaperTable& { return table(); },
        [&catalog]() -> const fl::assets::PartCatalog& { return catalog; });
    benchmark::DoNotOptimize(scene.frame->parts.size());
  }
}
BENCHMARK(BM_LoadSceneWith300Parts)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
