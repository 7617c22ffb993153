// Proves that we compile with exactly the flags of the Bullet library we link: double precision
// headers (BT_USE_DOUBLE_PRECISION) with the *-float64 libraries. btIsDoublePrecision() reads only
// our own headers, so these tests call into the library and check what comes back.
#include <cmath>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

namespace {

static_assert(sizeof(btScalar) == sizeof(double), "frictionlab uses Bullet in double precision");

// A direct (non-virtual) call: with mismatched precision it would not even link, and with a
// mismatched layout the inertia would come back wrong.
TEST(BulletPrecision, LibraryRoutineComputesTheBoxInertiaInDouble) {
  btBoxShape box(btVector3(0.1, 0.03, 0.0025));
  btVector3 inertia(0, 0, 0);
  const btScalar mass = 0.05;
  box.btBoxShape::calculateLocalInertia(mass, inertia);
  // Bullet's box inertia uses the full extents, margin included: m/12 (b^2 + c^2) with b = 2 *
  // 0.03.
  const double lx = 0.2, ly = 0.06, lz = 0.005;
  EXPECT_NEAR(inertia.x(), mass / 12.0 * (ly * ly + lz * lz), 1e-15);
  EXPECT_NEAR(inertia.y(), mass / 12.0 * (lx * lx + lz * lz), 1e-15);
  EXPECT_NEAR(inertia.z(), mass / 12.0 * (lx * lx + ly * ly), 1e-15);
  EXPECT_TRUE(btIsDoublePrecision());
}

// A 1 s free fall from 10 m through the library's world and integrator, at a fixed step:
// semi-implicit Euler gives z_n = z_0 - g dt^2 n (n + 1) / 2 exactly (to double rounding).
// A precision mismatch ended at z = 1.0 here (docs/physics.md).
TEST(BulletPrecision, FreeFallThroughTheLibraryWorldMatchesTheIntegratorInDouble) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, 0, -9.81));
  btSphereShape sphere(0.01);
  btVector3 inertia(0, 0, 0);
  sphere.calculateLocalInertia(1.0, inertia);
  btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 10)));
  btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(1.0, &motion, &sphere, inertia));
  body.setActivationState(DISABLE_DEACTIVATION);
  world.addRigidBody(&body);
  const double dt = 1.0 / 240.0;
  const int n = 240;
  for (int i = 0; i < n; ++i) world.stepSimulation(dt, 0);
  const double expected = 10.0 - 9.81 * dt * dt * n * (n + 1) / 2.0;  // 5.0746875
  EXPECT_NEAR(body.getCenterOfMassPosition().z(), expected, 1e-9);
  EXPECT_NEAR(body.getLinearVelocity().z(), -9.81 * n * dt, 1e-9);
  world.removeRigidBody(&body);
}

}  // namespace
