// The lab's phones, simulate -> file -> estimate: the paper's rig run for 30 s with a phone's
// magnetometer beside it (100 Hz) or its accelerometer on the plate (400 Hz, with or without g,
// turned or not), each file in phyphox's CSV form read back by `estimate` as phyphox's. The
// period comes back within 0.05 % of the run's own (its trajectory's); the accelerometer's phone
// raises the plate's centre of mass, and mu_k through the thick formula with that h_c is the
// scene's mu_k; its amplitude is the plate's.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/run/phone_csv.hpp"
#include "lab/run/run_outputs.hpp"
#include "support/scene_fixture.hpp"
#include "support/temp_folder.hpp"

namespace fl {
namespace {

struct PhoneCase {
  const char* name;
  const char* phone;       // the scene's phones entry
  const char* file;        // what the run writes
  const char* instrument;  // what estimate says it read
  const char* channel;     // the channel it chose
};

class PhoneRoundTrip : public test::TempFolderTest,
                       public ::testing::WithParamInterface<PhoneCase> {
 protected:
  PhoneRoundTrip() : TempFolderTest("frictionlab-phone-round-trip") {}
};

TEST_P(PhoneRoundTrip, EstimateReadsThePhonesFileAsPhyphoxsAndFindsTheRunsPeriod) {
  const PhoneCase& c = GetParam();
  const std::vector<SceneOverride> overrides = {{"world.duration", "30 s"},
                                                {"phones", std::string("[") + c.phone + "]"}};
  const Scene scene = test::scene_file("paper-rig.yaml", overrides);
  const CompiledRig rig = compile_rig(scene);
  ASSERT_EQ(phone_csv_name(rig, 0), c.file);
  RunRecording recording;
  const RunSummary run = run_experiment(rig, recording_for(scene.output), &recording);
  ASSERT_TRUE(run.period_trajectory.has_value());
  write_run_outputs(dir_.string(), scene.output, rig, run, recording);

  const HallLog log = read_hall_log((dir_ / c.file).string(), HallLogOptions{});
  EXPECT_EQ(instrument_words(log.instrument), c.instrument);
  EXPECT_EQ(log.channel, c.channel);
  LogSetUp set_up;
  set_up.spacing = rig.rollers.spacing;
  set_up.gravity = rig.world.gravity;
  set_up.h_c = rig.plate.h_c;
  const LogEstimate estimate = estimate_log(log, set_up, false);
  require_periods(log, estimate, "");
  EXPECT_GE(estimate.stats.periods_used, 35u);  // 38 periods in 30 s, less the first
  const double truth = *run.period_trajectory;
  EXPECT_NEAR(estimate.stats.period_s, truth, 5e-4 * truth);
  // The phone on the plate is in h_c: the thick formula gives back the scene's mu_k (the
  // trajectory's period sits within 0.001 % of the thick formula's, docs/physics.md).
  ASSERT_TRUE(mu_k_thick(estimate).has_value());
  EXPECT_NEAR(*mu_k_thick(estimate), scene.friction.mu_k, 1e-3 * scene.friction.mu_k);
  if (log.half_swing) {
    // An accelerometer's swing over omega^2: the plate's 30 mm.
    const std::optional<double> amplitude = plate_amplitude(log, estimate);
    ASSERT_TRUE(amplitude.has_value());
    EXPECT_NEAR(*amplitude, *run.amplitude_start, 0.01 * *run.amplitude_start);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Phones, PhoneRoundTrip,
    ::testing::Values(
        PhoneCase{"magnetometer_beside_the_rig",
                  "{sensor: magnetometer, position: [114 mm, 60 mm, -10 mm]}",
                  "phone-magnetometer.csv", "phyphox magnetometer", "|B|"},
        PhoneCase{"accelerometer_on_the_bricks", "{sensor: accelerometer, height: 9.6 mm}",
                  "phone-accelerometer.csv", "phyphox accelerometer", "y"},
        PhoneCase{"linear_accelerometer_turned",
                  "{sensor: accelerometer, gravity: false, turn: 60 deg, height: 9.6 mm}",
                  "phone-accelerometer.csv", "phyphox accelerometer (without g)",
                  "0.866 x + 0.500 y"}),
    [](const ::testing::TestParamInfo<PhoneCase>& p) { return p.param.name; });

}  // namespace
}  // namespace fl
