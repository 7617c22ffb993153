#include "physics/rig_world.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <btBulletDynamicsCommon.h>

namespace fl {
namespace {

// Bullet combines two bodies' friction as their product clamped to 10. We give the rollers
// friction 1 and the plate mu_k, and combine without the clamp, so the plate-roller
// coefficient is exactly the scene's mu_k (also above 10).
btScalar combine_friction_unclamped(const btCollisionObject* a, const btCollisionObject* b) {
  return a->getFriction() * b->getFriction();
}

struct FrictionCallbackInstaller {
  FrictionCallbackInstaller() { gCalculateCombinedFrictionCallback = &combine_friction_unclamped; }
};

}  // namespace

struct RigWorld::Impl {
  Scene scene;
  PlateMass mass;
  double dt = 0.0;
  long long steps = 0;
  std::array<double, 2> roller_omega{};

  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};

  std::unique_ptr<btSphereShape> roller_shape;
  std::array<std::unique_ptr<btRigidBody>, 2> rollers;
  std::unique_ptr<btBoxShape> plate_shape;
  std::unique_ptr<btRigidBody> plate;

  explicit Impl(const Scene& s);
  ~Impl();

  // Before each internal step: kinematic rollers keep a fixed transform and a forced angular
  // velocity (Bullet would otherwise derive their velocity from a changing transform, which
  // aliases at large steps and leaves stale contact points; ../shared/bullet-facts.md).
  static void force_roller_speeds(btDynamicsWorld* world, btScalar /*time_step*/) {
    auto* impl = static_cast<Impl*>(world->getWorldUserInfo());
    for (int i = 0; i < 2; ++i) {
      impl->rollers[i]->setAngularVelocity(btVector3(0, impl->roller_omega[i], 0));
      impl->rollers[i]->setLinearVelocity(btVector3(0, 0, 0));
    }
  }
};

RigWorld::Impl::Impl(const Scene& s) : scene(s), mass(fl::plate_mass(s)), dt(s.world.time_step) {
  static const FrictionCallbackInstaller install;
  world.setGravity(btVector3(0, 0, -s.world.gravity));
  btContactSolverInfo& info = world.getSolverInfo();
  info.m_numIterations = s.world.solver_iterations;

  // Rollers: kinematic, fixed in place, turning at the set speed. For collision each is one
  // sphere of the roller's radius (a cylinder against a box gives one contact point that jumps
  // between the plate's edges; ../shared/bullet-facts.md); the renderer draws the cylinder.
  const double l = s.rollers.spacing;
  const double a = s.rollers.radius;
  const double sense = s.rollers.sense == RollerSense::kInward ? 1.0 : -1.0;
  // Roller 0 at -l/2 turns about +y so its top moves toward +x (the centre) when inward.
  roller_omega = {sense * s.rollers.speed, -sense * s.rollers.speed};
  roller_shape = std::make_unique<btSphereShape>(a);
  for (int i = 0; i < 2; ++i) {
    const double x = (i == 0 ? -0.5 : 0.5) * l;
    btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, roller_shape.get());
    ci.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), btVector3(x, 0, -a));
    ci.m_friction = 1.0;
    ci.m_restitution = 0.0;
    ci.m_rollingFriction = 0.0;
    ci.m_spinningFriction = 0.0;
    rollers[i] = std::make_unique<btRigidBody>(ci);
    rollers[i]->setCollisionFlags(rollers[i]->getCollisionFlags() |
                                  btCollisionObject::CF_KINEMATIC_OBJECT);
    rollers[i]->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(rollers[i].get());
  }

  // The plate: its centre of mass is the body's origin. For collision it is a box whose bottom
  // face lies h_c below the centre of mass (the contact line), as long and wide as the plate;
  // only that face and the sides ever touch anything. Mass and pitch inertia come from the
  // parts (slab, payload, magnets), not from the box.
  const PlateDesc& p = s.plate;
  plate_shape = std::make_unique<btBoxShape>(btVector3(0.5 * p.length, 0.5 * p.width, mass.h_c));
  // Inertia about x and z does not act (the motion is planar) but must be positive.
  const btVector3 inertia(mass.inertia_pitch, mass.inertia_pitch, mass.inertia_pitch);
  btRigidBody::btRigidBodyConstructionInfo ci(mass.mass, nullptr, plate_shape.get(), inertia);
  ci.m_startWorldTransform =
      btTransform(btQuaternion::getIdentity(), btVector3(p.offset, 0, mass.h_c));
  ci.m_friction = s.friction.mu_k;
  ci.m_restitution = 0.0;
  ci.m_rollingFriction = 0.0;
  ci.m_spinningFriction = 0.0;
  ci.m_linearDamping = 0.0;
  ci.m_angularDamping = 0.0;
  plate = std::make_unique<btRigidBody>(ci);
  plate->setActivationState(DISABLE_DEACTIVATION);
  // The minimal scene has no guides: the plate moves in the x-z plane and pitches about y.
  plate->setLinearFactor(btVector3(1, 0, 1));
  plate->setAngularFactor(btVector3(0, 1, 0));
  plate->setLinearVelocity(btVector3(p.velocity, 0, 0));
  world.addRigidBody(plate.get());

  world.setInternalTickCallback(&force_roller_speeds, this, /*isPreTick=*/true);
}

RigWorld::Impl::~Impl() {
  world.removeRigidBody(plate.get());
  for (auto& r : rollers) world.removeRigidBody(r.get());
}

RigWorld::RigWorld(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {}
RigWorld::~RigWorld() = default;

void RigWorld::step() {
  impl_->world.stepSimulation(impl_->dt, 0);
  ++impl_->steps;
}

double RigWorld::time() const {
  return static_cast<double>(impl_->steps) * impl_->dt;
}
long long RigWorld::steps() const {
  return impl_->steps;
}

PlateState RigWorld::plate() const {
  const btRigidBody& b = *impl_->plate;
  const btTransform& t = b.getCenterOfMassTransform();
  PlateState s;
  s.x = t.getOrigin().x();
  s.z = t.getOrigin().z();
  // Rotation about y only: the x axis of the body is (cos p, 0, -sin p).
  const btVector3 ex = t.getBasis().getColumn(0);
  s.pitch = std::atan2(-ex.z(), ex.x());
  s.vx = b.getLinearVelocity().x();
  s.vz = b.getLinearVelocity().z();
  s.pitch_rate = b.getAngularVelocity().y();
  return s;
}

std::array<RollerContact, 2> RigWorld::contacts() const {
  std::array<RollerContact, 2> out{};
  const int n = impl_->dispatcher.getNumManifolds();
  for (int m = 0; m < n; ++m) {
    const btPersistentManifold* manifold = impl_->dispatcher.getManifoldByIndexInternal(m);
    for (int i = 0; i < 2; ++i) {
      const btCollisionObject* roller = impl_->rollers[i].get();
      const bool plate_first = manifold->getBody0() == impl_->plate.get();
      if (!((plate_first && manifold->getBody1() == roller) ||
            (!plate_first && manifold->getBody0() == roller &&
             manifold->getBody1() == impl_->plate.get())))
        continue;
      for (int k = 0; k < manifold->getNumContacts(); ++k) {
        const btManifoldPoint& pt = manifold->getContactPoint(k);
        // The normal points from body1 to body0; we want forces on the plate.
        const double sign = plate_first ? 1.0 : -1.0;
        const btVector3 normal = sign * pt.m_normalWorldOnB;
        const btVector3 impulse = normal * pt.getAppliedImpulse() +
                                  sign * pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                                  sign * pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
        out[i].touching =
            out[i].touching || pt.getDistance() <= 0.0 || pt.getAppliedImpulse() > 0.0;
        out[i].normal_force += impulse.z() / impl_->dt;
        out[i].friction_force += impulse.x() / impl_->dt;
        out[i].penetration = std::max(out[i].penetration, -static_cast<double>(pt.getDistance()));
      }
    }
  }
  return out;
}

std::array<double, 2> RigWorld::roller_speeds() const {
  return impl_->roller_omega;
}

std::array<double, 2> RigWorld::roller_surface_speeds() const {
  const double a = impl_->scene.rollers.radius;
  return {impl_->roller_omega[0] * a, impl_->roller_omega[1] * a};
}

double RigWorld::plate_mass() const {
  return impl_->mass.mass;
}
double RigWorld::plate_h_c() const {
  return impl_->mass.h_c;
}
double RigWorld::plate_inertia() const {
  return impl_->mass.inertia_pitch;
}

}  // namespace fl
