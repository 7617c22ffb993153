// A payload off the plate's middle (plate.payload.x): the plate's centre of mass lies
// m_payload x / m from its middle, and the rollers, which see only the centre of mass, give it
// the thick plate's period about the rollers' midpoint, whatever x: the friction's restoring force
// and the normal forces' share depend on where the centre of mass is, not on where the plate's
// middle is.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lab/run/experiment.hpp"
#include "scene/compiled_rig.hpp"
#include "support/scene_fixture.hpp"

namespace fl {
namespace {

TEST(PayloadOffset, TheCentreOfMassMovesAndThePeriodDoesNot) {
  const std::vector<SceneOverride> level{
      {"plate.payload.mass", "50 g"}, {"plate.payload.height", "5 mm"}, {"world.duration", "15 s"}};
  const CompiledRig middle = compile_rig(test::minimal_without_sensor(level));
  for (const char* x : {"-40 mm", "25 mm"}) {
    std::vector<SceneOverride> keys = level;
    keys.push_back({"plate.payload.x", x});
    const CompiledRig rig = compile_rig(test::minimal_without_sensor(keys));
    const double payload_x = std::stod(x) * 1e-3;
    // The centre of mass: the payload's moment over the whole plate's mass (the rest of the
    // plate's parts as they were).
    EXPECT_NEAR(rig.plate.x_c - middle.plate.x_c, 0.050 * payload_x / rig.plate.mass, 1e-12) << x;
    EXPECT_NEAR(rig.plate.h_c, middle.plate.h_c, 1e-15) << x;
    const RunSummary r = run_experiment(rig, {});
    ASSERT_EQ(r.regime, Regime::kOscillates) << x << ": " << r.regime_evidence;
    ASSERT_TRUE(r.period_trajectory && r.oscillation_centre) << x;
    const double mu = rig.friction.mu_k, h_c = rig.plate.h_c, l = rig.rollers.spacing;
    const double period =
        2.0 * std::numbers::pi * std::sqrt((l - 2.0 * mu * h_c) / (2.0 * mu * 9.81));
    EXPECT_NEAR(*r.period_trajectory / period, 1.0, 1e-4) << x;
    EXPECT_NEAR(*r.oscillation_centre, 0.0, 0.05e-3) << x;
  }
}

}  // namespace
}  // namespace fl
