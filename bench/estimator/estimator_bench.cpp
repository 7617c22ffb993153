// Samples per second of the host build of the rig's period estimator on one core (the lab's
// target: 50 million or more). The samples are made beforehand
// (tests/estimator/synthetic_hall.hpp): only add_sample is timed.
#include <benchmark/benchmark.h>

#include "estimator/period_estimator.h"
#include "estimator/synthetic_hall.hpp"

namespace {

fl::test::HallSamples make_samples(double rate_hz, double sensor_offset_m) {
  fl::test::HallSignal s;
  s.sample_rate_hz = rate_hz;
  s.duration_s = 2e6 / rate_hz;  // two million samples
  s.sensor_offset_m = sensor_offset_m;
  s.noise_counts = 2.0;
  s.drift_counts_per_s = 0.5;
  return fl::test::generate(s);
}

void feed(benchmark::State& state, const fl::test::HallSamples& samples) {
  uint64_t periods = 0;
  for (auto _ : state) {
    fl_estimator::PeriodEstimator estimator;
    uint32_t events = 0;
    for (std::size_t i = 0; i < samples.adc.size(); ++i)
      events += estimator.add_sample(samples.t_us[i], samples.adc[i]);
    benchmark::DoNotOptimize(events);
    periods += estimator.stats().periods_used;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(samples.adc.size()));
  state.counters["periods"] =
      static_cast<double>(periods) / static_cast<double>(state.iterations());
}

void BM_OnePulse10kHz(benchmark::State& state) {
  static const fl::test::HallSamples samples = make_samples(10000.0, 0.003);
  feed(state, samples);
}
BENCHMARK(BM_OnePulse10kHz)->Unit(benchmark::kMillisecond);

void BM_Pair10kHz(benchmark::State& state) {
  static const fl::test::HallSamples samples = make_samples(10000.0, -0.010);
  feed(state, samples);
}
BENCHMARK(BM_Pair10kHz)->Unit(benchmark::kMillisecond);

void BM_OnePulse1kHz(benchmark::State& state) {
  static const fl::test::HallSamples samples = make_samples(1000.0, 0.003);
  feed(state, samples);
}
BENCHMARK(BM_OnePulse1kHz)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
