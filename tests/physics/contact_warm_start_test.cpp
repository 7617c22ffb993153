// The solver's start on the roller contacts (physics/contact_warm_start.hpp), against the
// thick-plate statics: a plate resting on two rollers that slip under it, at offset x from the
// centre, carries N0 = m g (l/2 - x - mu h_c) / (l - 2 mu h_c) on the roller at -l/2 and
// N1 = m g (l/2 + x - mu h_c) / (l - 2 mu h_c) on the other (vertical force and pitch moment
// about the centre of mass in balance, the friction mu N acting h_c below it), with friction
// +mu N0 and -mu N1 along x from rollers turning inward. Started there, one Gauss-Seidel
// iteration is the whole solve; from Bullet's own start one iteration leaves the centred plate's
// roller 0 with 0.388 N where the statics need 0.309 N.
#include <algorithm>
#include <numbers>

#include <gtest/gtest.h>

#include "physics/rig_world.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {
namespace {

Scene plate_on_rollers(double offset, int iterations) {
  Scene s;
  s.friction.mu_k = 0.29;
  s.rollers.spacing = 0.089;
  s.rollers.radius = 0.010;
  s.plate.offset = offset;
  s.world.solver_iterations = iterations;
  return s;
}

TEST(SolverStart, OneIterationGivesTheThickPlatesStaticSplit) {
  for (const double offset : {0.0, 0.010, -0.025}) {
    SCOPED_TRACE(offset);
    const CompiledRig rig = compile_rig(plate_on_rollers(offset, 1));
    RigWorld world(rig);
    world.step();
    const double m = rig.plate.mass, g = rig.world.gravity, l = rig.rollers.spacing;
    const double mu = rig.friction.mu_k, h = rig.plate.h_c, x = offset;
    const double n0 = m * g * (0.5 * l - x - mu * h) / (l - 2.0 * mu * h);
    const double n1 = m * g * (0.5 * l + x - mu * h) / (l - 2.0 * mu * h);
    const auto c = world.contacts();
    ASSERT_TRUE(c[0].touching && c[1].touching);
    EXPECT_NEAR(c[0].normal_force, n0, 1e-9 * m * g);
    EXPECT_NEAR(c[1].normal_force, n1, 1e-9 * m * g);
    EXPECT_NEAR(c[0].friction_force, mu * n0, 1e-9 * m * g);
    EXPECT_NEAR(c[1].friction_force, -mu * n1, 1e-9 * m * g);
    EXPECT_EQ(world.solver_iterations_used(), 1);
  }
}

// At the scene's 10 iterations the solver stops after the first while both rollers slip: every
// step of 2 s of oscillation.
TEST(SolverStart, ASlidingStepStopsAfterOneIteration) {
  RigWorld world(plate_on_rollers(0.020, 10));
  for (int i = 0; i < 2000; ++i) {
    world.step();
    const auto c = world.contacts();
    ASSERT_TRUE(c[0].touching && c[1].touching && !c[0].stuck && !c[1].stuck) << i;
    EXPECT_EQ(world.solver_iterations_used(), 1) << "step " << i;
  }
}

// A plate stuck on a roller (rollers at 6 rpm, slower than the plate gets): the stuck contact
// starts from Bullet's own warm start, and the solver iterates; it stops early only once an
// iteration no longer changes anything.
TEST(SolverStart, AStuckStepIterates) {
  Scene scene = plate_on_rollers(0.020, 10);
  scene.rollers.speed = 6.0 * 2.0 * std::numbers::pi / 60.0;
  RigWorld world(scene);
  int stuck_steps = 0, most = 0;
  for (int i = 0; i < 2000; ++i) {
    world.step();
    const auto c = world.contacts();
    if (c[0].stuck || c[1].stuck) {
      ++stuck_steps;
      most = std::max(most, world.solver_iterations_used());
    }
  }
  EXPECT_GT(stuck_steps, 0);
  EXPECT_GT(most, 1);
}

}  // namespace
}  // namespace fl
