// The closed-form sphere-box contact against an independent finder of the same contact: Bullet's
// general convex test (GJK with the shapes' margins), which the rig's world used before. Over
// spheres all around and above a rounded box, turned and moved, the two agree on the normal, the
// point and the distance to rounding; and in a world the closed form gives the contact that GJK's
// world gives, step by step.
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <string>

#include "physics/roller_plate_contact.hpp"

namespace fl {
namespace {

struct GjkContact {
  bool found = false;
  btVector3 normal_on_b;
  btVector3 point_on_b;
  btScalar distance = 0;
};

// GJK between a sphere (A) and a box (B), as Bullet's convex-convex algorithm calls it.
GjkContact gjk(const btSphereShape& sphere, const btTransform& at, const btBoxShape& box,
               const btTransform& box_at) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector detector(&sphere, &box, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = at;
  input.m_transformB = box_at;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  btPointCollector collector;
  detector.getClosestPoints(input, collector, nullptr);
  return {collector.m_hasResult, collector.m_normalOnBInWorld, collector.m_pointInWorld,
          collector.m_distance};
}

TEST(SphereBoxContact, AgreesWithBulletsGjkAllAroundATurnedBox) {
  // The plate of the minimal scene (200 x 60 mm, h_c 2.5 mm below its centre of mass) and a
  // roller of 10 mm.
  btBoxShape box(btVector3(0.1, 0.03, 0.0025));
  btSphereShape sphere(0.01);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 2000; ++k) {
    btTransform box_at(
        btQuaternion(btVector3(unit(random), unit(random), unit(random)).normalized(),
                     0.5 * unit(random)),
        btVector3(0.05 * unit(random), 0.05 * unit(random), 0.05 * unit(random)));
    // A centre within 12 mm of the box's surface, outside its core: the separations and the
    // overlaps (down to 2 mm) a rig's contact sees.
    const btVector3 local(0.12 * unit(random), 0.04 * unit(random), 0.0025 + 0.01 * unit(random));
    const btVector3 centre = box_at * local;
    const SphereBoxContact c = sphere_box_contact(
        centre, sphere.getMargin(), box_at, box.getHalfExtentsWithoutMargin(), box.getMargin());
    if (c.distance + sphere.getMargin() + box.getMargin() < 1e-4) continue;  // GJK hands to EPA
    const GjkContact g = gjk(sphere, btTransform(btQuaternion::getIdentity(), centre), box, box_at);
    ASSERT_TRUE(g.found) << k;
    ++compared;
    // GJK stops when its simplex stops improving by a relative 1e-12 or so.
    EXPECT_NEAR(c.distance, g.distance, 1e-12) << k;
    EXPECT_NEAR((c.normal_on_box - g.normal_on_b).length(), 0.0, 1e-9) << k;
    EXPECT_NEAR((c.point_on_box - g.point_on_b).length(), 0.0, 1e-12) << k;
  }
  EXPECT_GT(compared, 1500);
}

TEST(SphereBoxContact, ASphereOnTheFaceTouchesAtItsFoot) {
  // A sphere of 10 mm resting 0.1 mm into a level box's top face, its margin included.
  btBoxShape box(btVector3(0.1, 0.03, 0.0025));
  const btVector3 half = box.getHalfExtentsWithoutMargin();
  const btScalar top = half.z() + box.getMargin();
  const btVector3 centre(0.02, 0.0, top + 0.01 - 1e-4);
  const SphereBoxContact c =
      sphere_box_contact(centre, 0.01, btTransform::getIdentity(), half, box.getMargin());
  EXPECT_NEAR(c.distance, -1e-4, 1e-15);
  EXPECT_NEAR((c.normal_on_box - btVector3(0, 0, 1)).length(), 0.0, 1e-15);
  EXPECT_NEAR((c.point_on_box - btVector3(0.02, 0.0, top)).length(), 0.0, 1e-15);
  EXPECT_NEAR((c.point_on_sphere - btVector3(0.02, 0.0, top - 1e-4)).length(), 0.0, 1e-15);
}

// A plate dropped on two sphere rollers and held to the x-z plane as the rig holds it, stepped in
// two worlds, one with the closed form and one with GJK: the plate moves the same way at every
// step. GJK's distances stop a relative 1e-12 or so short of exact and its normals carry a
// sideways part of about 1e-17 (which a free plate, rolling on two spheres, amplifies tenfold a
// step: this test's plate is planar, like the rig's); a contact found wrongly (a point missing, a
// normal turned) would move the plate by its penetration, some micrometres. 1e-12 m tells them
// apart.
TEST(SphereBoxContact, AWorldStepsAsWithGjk) {
  struct World {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    btSphereShape roller{0.01};
    btBoxShape plate_shape{btVector3(0.1, 0.03, 0.0025)};
    btRigidBody left{0.0, nullptr, &roller};
    btRigidBody right{0.0, nullptr, &roller};
    std::unique_ptr<btRigidBody> plate;

    explicit World(bool closed_form) {
      if (closed_form) use_closed_form_sphere_box_contact(dispatcher);
      world.setGravity(btVector3(0, 0, -9.81));
      left.setWorldTransform(
          btTransform(btQuaternion::getIdentity(), btVector3(-0.0445, 0, -0.01)));
      right.setWorldTransform(
          btTransform(btQuaternion::getIdentity(), btVector3(0.0445, 0, -0.01)));
      world.addRigidBody(&left);
      world.addRigidBody(&right);
      btVector3 inertia;
      plate_shape.calculateLocalInertia(0.05, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(0.05, nullptr, &plate_shape, inertia);
      info.m_startWorldTransform =
          btTransform(btQuaternion(btVector3(0, 1, 0), 0.01), btVector3(0.01, 0, 0.004));
      plate = std::make_unique<btRigidBody>(info);
      plate->setActivationState(DISABLE_DEACTIVATION);
      // In the x-z plane, pitching about y, as the rig holds it (physics/rig_world.cpp).
      plate->setLinearFactor(btVector3(1, 0, 1));
      plate->setAngularFactor(btVector3(0, 1, 0));
      world.addRigidBody(plate.get());
    }
    ~World() {
      world.removeRigidBody(plate.get());
      world.removeRigidBody(&right);
      world.removeRigidBody(&left);
    }
  };
  World closed(true);
  World general(false);
  double largest = 0.0;
  for (int step = 0; step < 500; ++step) {
    closed.world.stepSimulation(1e-3, 0);
    general.world.stepSimulation(1e-3, 0);
    const btVector3 a = closed.plate->getCenterOfMassPosition();
    const btVector3 b = general.plate->getCenterOfMassPosition();
    largest = std::max(largest, static_cast<double>((a - b).length()));
    ASSERT_LT((a - b).length(), 1e-12) << "step " << step;
  }
  std::ostringstream text;
  text << largest;
  RecordProperty("largest_difference_m", text.str());
  // It came to rest on both rollers.
  EXPECT_EQ(closed.dispatcher.getNumManifolds(), 2);
  for (int m = 0; m < 2; ++m)
    EXPECT_EQ(closed.dispatcher.getManifoldByIndexInternal(m)->getNumContacts(), 1);
}

}  // namespace
}  // namespace fl
