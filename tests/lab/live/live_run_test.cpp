// A live run (the browser's session) against the run `frictionlab run` makes: the same summary and
// files byte for byte, whatever pace the frames are taken at, and frames that hand out each Hall
// sample, pulse and period once, in order.
#include "lab/live/live_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
  int first_way = 0;  // the plate's first way, +1 or -1
  bool turned = false;
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
    // A regime once the plate has turned (the trajectory shows the oscillation then), none before.
    const int way = frame.plate.vx > 0.0 ? 1 : frame.plate.vx < 0.0 ? -1 : 0;
    if (first_way == 0) first_way = way;
    turned = turned || (way != 0 && way != first_way);
    if (turned) {
      EXPECT_FALSE(frame.regime.empty()) << "t = " << frame.t;
    }
  }
  EXPECT_TRUE(turned);
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

// The theory a live frame carries (the page draws it as sent): on a rig tilted by 3 degrees it
// starts where the plate does and oscillates about x_eq, down the slope, not about the middle;
// and the simulated plate follows it to within the integrator's phase error over three periods.
TEST(LiveRun, FramesCarryTheTheoryAboutATiltedRigsCentre) {
  const Scene scene = test::scene_file(
      "minimal.yaml",
      std::vector<SceneOverride>{{"world.tilt", "3 deg"}, {"world.duration", "3 s"}});
  const std::shared_ptr<const CompiledRig> rig = rig_of(scene);
  ASSERT_TRUE(rig->oscillation_centre && rig->omega);
  const double centre = *rig->oscillation_centre;
  EXPECT_LT(centre, -1e-3);  // x_eq = -(l - 2 mu_k h_c) tan(alpha) / (2 mu_k): millimetres
  LiveRun live(rig, scene.output);
  LiveFrame first = live.advance_to(0.0);
  ASSERT_TRUE(first.x_theory.has_value());
  EXPECT_NEAR(*first.x_theory, first.plate.x, 1e-12);
  double lowest = 1.0, highest = -1.0, worst = 0.0;
  for (double t = 0.01; !live.ended(); t += 0.01) {
    const LiveFrame f = live.advance_to(t);
    ASSERT_TRUE(f.x_theory.has_value());
    lowest = std::min(lowest, *f.x_theory);
    highest = std::max(highest, *f.x_theory);
    worst = std::max(worst, std::fabs(f.plate.x - *f.x_theory));
  }
  // Its turning points straddle x_eq symmetrically (sampled every 10 ms: within omega^2 A dt^2).
  EXPECT_NEAR(0.5 * (lowest + highest), centre, 2e-5);
  // The simulated plate lags theory by the semi-implicit Euler step's half step, omega dt / 2 of
  // phase from its start at rest (A omega dt / 2 of position, A = |x0 - x_eq|), plus its
  // (omega dt)^2 / 24 of period over the run: nothing else.
  const double amplitude = std::fabs(first.plate.x - centre);
  const double omega = *rig->omega, dt = rig->world.time_step;
  EXPECT_LT(worst, 1.05 * amplitude * omega * dt / 2.0 +
                       amplitude * omega * 3.0 * omega * dt * omega * dt / 24.0)
      << worst;
}

// A rig whose rollers turn outward restores nothing: no theory to draw.
TEST(LiveRun, RollersTurningOutwardHaveNoTheory) {
  const Scene scene = test::scene_file(
      "minimal.yaml",
      std::vector<SceneOverride>{{"rollers.sense", "outward"}, {"world.duration", "0.1 s"}});
  LiveRun live(rig_of(scene), scene.output);
  EXPECT_FALSE(live.advance_to(0.05).x_theory.has_value());
}

}  // namespace
}  // namespace fl
