// A live run (the browser's session) against the run `frictionlab run` makes: the same summary and
// files byte for byte, whatever pace the frames are taken at, and frames that hand out each Hall
// sample, pulse and period once, in order.
#include "lab/live/live_run.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lab/run/run_outputs.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

std::shared_ptr<const CompiledRig> rig_of(const Scene& scene) {
  return compile_rig_shared(scene);
}

// The files `run --out` writes for the scene, but timing.json (wall time).
std::vector<std::pair<std::string, std::string>> run_files(const Scene& scene) {
  const CompiledRig rig = compile_rig(scene);
  const RunOptions options = recording_for(scene.output);
  RunRecording recording;
  const RunSummary summary = run_experiment(rig, options, &recording);
  auto files = run_output_files(scene.output, rig, summary, recording);
  std::erase_if(files, [](const auto& f) { return f.first == "timing.json"; });
  return files;
}

void expect_same_files_as_run(const Scene& scene, double frame_interval) {
  LiveRun live(rig_of(scene), scene.output);
  double t = 0.0;
  while (!live.ended()) live.advance_to(t += frame_interval);
  for (const auto& [name, text] : run_files(scene)) {
    const std::optional<std::string> mine = live.file(name);
    ASSERT_TRUE(mine.has_value()) << name;
    EXPECT_TRUE(*mine == text) << name << " differs from run's";
  }
}

TEST(LiveRun, ItsFilesAreTheRunsByteForByte) {
  std::vector<SceneOverride> shorter{{"world.duration", "4 s"}};
  expect_same_files_as_run(test::scene_file("minimal.yaml", shorter), 1.0 / 30);
}

TEST(LiveRun, ThePaperRigsFilesAreTheRunsAtAnyPace) {
  std::vector<SceneOverride> shorter{{"world.duration", "3 s"}};
  const Scene scene = test::scene_file("paper-rig.yaml", shorter);
  // Real time, slow motion (1/16: a frame every 2 ms of simulated time), and one big stride.
  expect_same_files_as_run(scene, 1.0 / 30);
  expect_same_files_as_run(scene, 1.0 / 480);
  expect_same_files_as_run(scene, 10.0);
}

TEST(LiveRun, FramesHandOutEverySampleAndPeriodOnceInOrder) {
  std::vector<SceneOverride> shorter{{"world.duration", "8 s"}};
  const Scene scene = test::scene_file("minimal.yaml", shorter);
  LiveRun live(rig_of(scene), scene.output);
  std::vector<HallSample> samples;
  std::vector<double> pulses;
  std::vector<EstimatedPeriod> periods;
  double t = 0.0;
  double previous_t = -1.0;
  while (!live.ended()) {
    const LiveFrame frame = live.advance_to(t += 1.0 / 30);
    EXPECT_GT(frame.t, previous_t);
    // A frame reaches the time asked for, to within one step.
    if (!live.ended()) {
      EXPECT_NEAR(frame.t, t, scene.world.time_step + 1e-12);
    }
    previous_t = frame.t;
    samples.insert(samples.end(), frame.hall.begin(), frame.hall.end());
    pulses.insert(pulses.end(), frame.pulses.begin(), frame.pulses.end());
    periods.insert(periods.end(), frame.periods.begin(), frame.periods.end());
    EXPECT_FALSE(frame.regime.empty());
  }
  // The sensor samples at 1 kHz: one sample a millisecond over the run, each once.
  const double rate = scene.sensor->sample_rate;
  EXPECT_NEAR(static_cast<double>(samples.size()), rate * scene.world.duration, 2.0);
  for (std::size_t i = 1; i < samples.size(); ++i) ASSERT_GT(samples[i].t_us, samples[i - 1].t_us);
  for (std::size_t i = 1; i < pulses.size(); ++i) ASSERT_GT(pulses[i], pulses[i - 1]);
  // The periods handed out are the estimator's, as the summary counts them: T = pi sqrt(2 l /
  // (mu g)) corrected for the thick plate. Each period is timed between pulses the sensor
  // samples every millisecond: 1 ms in its 0.78 s is 1.3e-3, so within 2e-3.
  const RunSummary& summary = live.summary();
  ASSERT_TRUE(summary.estimator.has_value());
  int accepted = 0;
  for (const EstimatedPeriod& p : periods) accepted += p.status == fl_estimator::kAccepted;
  EXPECT_GE(accepted, 1);
  EXPECT_LE(accepted, summary.estimator->periods_used);
  const CompiledRig rig = compile_rig(scene);
  for (const EstimatedPeriod& p : periods)
    if (p.status == fl_estimator::kAccepted) {
      EXPECT_NEAR(p.period / *rig.period_thick, 1.0, 2e-3);
    }
}

TEST(LiveRun, NoFilesBeforeTheEnd) {
  const Scene scene = test::scene_file("minimal.yaml");
  LiveRun live(rig_of(scene), scene.output);
  live.advance_to(0.5);
  EXPECT_FALSE(live.ended());
  EXPECT_THROW(live.summary(), std::logic_error);
  EXPECT_THROW(live.file("summary.json"), std::logic_error);
}

}  // namespace
}  // namespace fl
