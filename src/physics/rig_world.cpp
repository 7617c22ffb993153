#include "physics/rig_world.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact_friction.hpp"
#include "physics/contact_warm_start.hpp"
#include "physics/drivetrain.hpp"
#include "physics/plate_manifold.hpp"
#include "physics/roller_plate_contact.hpp"

namespace fl {
namespace {

// Bullet's default pools hold 4096 manifolds and 4096 collision algorithms, allocated and cleared
// when a world is made: most of the cost of a short run. A rig has a few pairs (the plate against
// two rollers and the guides' boxes); past the pools Bullet allocates from the heap.
btDefaultCollisionConstructionInfo small_pools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 64;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  return info;
}

}  // namespace

struct RigWorld::Impl {
  // Bullet's world with the rig's friction applied after collision detection and before the
  // solver, each step: the one place the friction law acts (physics/contact_friction.hpp).
  class FrictionWorld final : public btDiscreteDynamicsWorld {
   public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    Impl* rig = nullptr;

   protected:
    void solveConstraints(btContactSolverInfo& info) override {
      if (rig != nullptr) rig->before_solve(info);
      btDiscreteDynamicsWorld::solveConstraints(info);
    }
  };

  std::shared_ptr<const CompiledRig> owned;  // when the world compiled its scene itself
  const CompiledRig& rig;
  double dt = 0.0;
  double contact_erp = 0.0;  // Bullet's position correction per step (m_erp2)
  long long steps = 0;
  std::array<double, 2> roller_omega{};
  std::array<double, 2> roller_angle{};
  // Each roller's axis: +y, or turned about +z by +skew/2 (roller 0) and -skew/2 (roller 1).
  std::array<btVector3, 2> roller_axis{btVector3(0, 1, 0), btVector3(0, 1, 0)};
  // What the rollers did to the plate in the last step, read once per step from the manifolds.
  std::array<RollerContact, 2> contacts{};

  btDefaultCollisionConfiguration configuration{small_pools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  RollerContactSolver solver;  // Bullet's, starting the roller contacts' friction too
  FrictionWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::unique_ptr<ContactFriction> friction;

  std::array<std::unique_ptr<btSphereShape>, 2> roller_shapes;
  std::array<std::unique_ptr<btRigidBody>, 2> rollers;
  std::unique_ptr<Drivetrain> drivetrain;  // the motor and gears (absent: the ideal drive)
  std::vector<std::unique_ptr<btBoxShape>> guide_shapes;
  std::vector<std::unique_ptr<btCollisionObject>> guides;
  std::unique_ptr<btBoxShape> plate_shape;
  std::unique_ptr<btRigidBody> plate;

  Impl(const CompiledRig& compiled, std::shared_ptr<const CompiledRig> keep);
  // The guide towers (the frame's parts marked as guides, each through its boxes), then the plate
  // on the rollers: parts of the constructor, in that order (the plate's freedom depends on the
  // guides).
  void add_guides();
  void add_plate();

  std::array<const btRigidBody*, 2> roller_bodies() const {
    return {rollers[0].get(), rollers[1].get()};
  }

  // After collision detection, before the solver: the friction law at every contact, then the
  // solver's start on the two roller contacts at their balance (physics/contact_warm_start.hpp).
  void before_solve(const btContactSolverInfo& info);

  // Reads the contact manifolds once per step, after it: the rollers' forces on the plate, and
  // each roller contact's impulses for the friction's stick test.
  std::array<RollerContact, 2> measure_contacts(
      std::array<ContactFriction::RollerImpulses, 2>& impulses) const;
  ~Impl();

  // With run-out the tubes' tops start off the contact line and moving up or down: the plate
  // starts resting on them (its bottom through both tops, moving with them), not dropped onto
  // them.
  void rest_on_off_centre_rollers() {
    const double l = rig.contact_spacing;
    const double e = rig.rollers.runout;
    std::array<double, 2> top{}, top_speed{};  // each top's height and vertical speed at t = 0
    for (std::size_t i = 0; i < 2; ++i) {
      const double angle = rig.rollers.runout_phase[i];
      top[i] = -e * std::sin(angle);
      top_speed[i] = -roller_omega[i] * e * std::cos(angle);
    }
    const double x = rig.plate_desc.offset;
    const double slope = (top[1] - top[0]) / l;
    const double bottom = 0.5 * (top[0] + top[1]) + slope * x;
    const double pitch = -std::atan(slope);  // the body's x axis is (cos p, 0, -sin p)
    btTransform t = plate->getWorldTransform();
    t.setOrigin(t.getOrigin() + btVector3(0, 0, bottom));
    t.setRotation(btQuaternion(btVector3(0, 1, 0), pitch));
    plate->setWorldTransform(t);
    const double slope_rate = (top_speed[1] - top_speed[0]) / l;
    btVector3 v = plate->getLinearVelocity();
    v.setZ(0.5 * (top_speed[0] + top_speed[1]) + slope_rate * x);
    plate->setLinearVelocity(v);
    plate->setAngularVelocity(btVector3(0, -slope_rate, 0));
  }

  // A roller with run-out: its tube's axis, e off the shaft, turns with the shaft, so the body sits
  // at the shaft + R_y(phi + theta) (e, 0, 0) (phi its phase, theta the shaft's angle about +y
  // since t = 0) and moves with omega x that offset. Set before each step from the angle at its
  // start.
  void place_off_centre(int i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const double e = rig.rollers.runout;
    const double angle = rig.rollers.runout_phase[k] + roller_angle[k];
    // R_y(theta) (e, 0, 0) = (e cos theta, 0, -e sin theta).
    const double ox = e * std::cos(angle);
    const double oz = -e * std::sin(angle);
    const double shaft_x = (i == 0 ? -0.5 : 0.5) * rig.contact_spacing;
    btTransform t = rollers[k]->getWorldTransform();
    t.setOrigin(btVector3(shaft_x + ox, 0, -rig.roller_radii[k] + oz));
    rollers[k]->setWorldTransform(t);
    const double w = roller_omega[k];
    rollers[k]->setLinearVelocity(btVector3(w * oz, 0, -w * ox));
  }

  // Before each internal step: kinematic rollers keep a fixed transform and a forced angular
  // velocity (Bullet would otherwise derive their velocity from a changing transform, which
  // aliases at large steps and leaves stale contact points; docs/physics.md). With a
  // drive, the speed is the gear train's (advanced in RigWorld::step).
  static void before_step(btDynamicsWorld* world, btScalar /*time_step*/) {
    auto* impl = static_cast<Impl*>(world->getWorldUserInfo());
    for (int i = 0; i < 2; ++i) {
      impl->rollers[i]->setAngularVelocity(impl->roller_axis[i] * impl->roller_omega[i]);
      impl->rollers[i]->setLinearVelocity(btVector3(0, 0, 0));
      if (impl->rig.rollers.runout > 0.0) impl->place_off_centre(i);
    }
  }
};

RigWorld::Impl::Impl(const CompiledRig& compiled, std::shared_ptr<const CompiledRig> keep)
    : owned(std::move(keep)), rig(compiled), dt(compiled.world.time_step) {
  const CompiledRig& s = rig;
  // The rollers' spheres against the plate's box in closed form, as GJK finds them but cheaper
  // (physics/roller_plate_contact.hpp).
  use_closed_form_sphere_box_contact(dispatcher);
  // The rig's frame stays level; a tilted rig turns gravity in it (scene.hpp, world.tilt; and
  // rollers of different radii, rig.contact_tilt).
  world.setGravity(btVector3(-s.world.gravity * std::sin(rig.contact_tilt), 0,
                             -s.world.gravity * std::cos(rig.contact_tilt)));
  btContactSolverInfo& info = world.getSolverInfo();
  info.m_numIterations = s.world.solver_iterations;
  // The iterations stop early once one changes no row's velocity by more than 1e-12 m/s (Bullet's
  // residual: the largest squared change, (m/s)^2). A step started at its balance
  // (physics/contact_warm_start.hpp) is then done after one iteration instead of repeating it;
  // Gauss-Seidel creeping on an ill-conditioned split (at most 0.9967 a step on the lab's
  // plates) with changes that small is within 3e-10 m/s of its answer, far inside the
  // convergence check's 1e-4 of the weight (1e-6 m/s at 1 ms), which still judges every step.
  info.m_leastSquaresResidualThreshold = 1e-24;
  contact_erp = info.m_erp2;
  // A stuck contact's friction directions are set per point (physics/contact_friction.hpp).
  info.m_solverMode |= SOLVER_ENABLE_FRICTION_DIRECTION_CACHING;

  // Rollers. For collision each is one sphere of the roller's radius (a cylinder against a box
  // gives one contact point that jumps between the plate's edges; docs/physics.md);
  // the renderer draws the cylinder. A roller with rolling resistance presses the plate through
  // a pressure centre delta ahead of its top: its sphere sits that much farther out (inward
  // rollers), the surface's speed unchanged (scene.hpp, rollers.rolling_resistance).
  // Rollers of different radii on axes at one height: the rig's frame is turned with the line
  // through their tops (rig.contact_tilt, with gravity), so in it the tops stand level, the axes
  // at -a_0 and -a_1, the tangent points l cos(asin((a_1 - a_0) / l)) apart (rig.contact_spacing).
  const double l = s.contact_spacing;
  for (std::size_t i = 0; i < 2; ++i)
    roller_shapes[i] = std::make_unique<btSphereShape>(rig.roller_radii[i]);
  // Skewed axes, turned about +z: (-sin phi, cos phi, 0) with phi = +skew/2 for roller 0 and
  // -skew/2 for roller 1. An inward roller's top then moves at v_r (cos phi, sin phi, 0) times its
  // sense: both tops move toward +y for skew > 0.
  for (std::size_t i = 0; i < 2; ++i) {
    const double phi = (i == 0 ? 0.5 : -0.5) * s.rollers.skew;
    roller_axis[i] = btVector3(-std::sin(phi), std::cos(phi), 0);
  }
  const double sense = s.rollers.sense == RollerSense::kInward ? 1.0 : -1.0;
  // The ideal drive: the set speed. Roller 0 at -l/2 turns about +y so its top moves toward +x
  // (the centre) when inward. With a drive, the gear train's (physics/drivetrain.hpp).
  const double speed = rig.roller_speed_ramp ? rig.roller_speed_ramp->at(0.0) : s.rollers.speed;
  const double speed_1 = rig.roller_speed_ramp_roller_1 ? rig.roller_speed_ramp_roller_1->at(0.0)
                                                        : s.rollers.speed_roller_1.value_or(speed);
  roller_omega = {sense * speed, -sense * speed_1};
  if (s.drive) {
    drivetrain = std::make_unique<Drivetrain>(rig);
    roller_omega = drivetrain->roller_speeds();
  }
  for (int i = 0; i < 2; ++i) {
    const double x = (i == 0 ? -0.5 : 0.5) * l;
    const double a = rig.roller_radii[static_cast<std::size_t>(i)];
    btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr,
                                                roller_shapes[static_cast<std::size_t>(i)].get());
    ci.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), btVector3(x, 0, -a));
    ci.m_friction = 0.0;  // per contact point (ContactFriction)
    ci.m_restitution = 0.0;
    ci.m_rollingFriction = 0.0;
    ci.m_spinningFriction = 0.0;
    rollers[i] = std::make_unique<btRigidBody>(ci);
    rollers[i]->setCollisionFlags(rollers[i]->getCollisionFlags() |
                                  btCollisionObject::CF_KINEMATIC_OBJECT);
    rollers[i]->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(rollers[i].get());
    if (s.rollers.runout > 0.0) place_off_centre(i);
  }

  add_guides();
  add_plate();

  world.setInternalTickCallback(&before_step, this, /*isPreTick=*/true);
  friction = std::make_unique<ContactFriction>(rig.friction, rig.guide_friction, plate.get(),
                                               roller_bodies());
  world.rig = this;
}

void RigWorld::Impl::add_guides() {
  const CompiledRig& s = rig;
  // Guide towers: only the frame's parts marked as guides collide, each through its boxes
  // (from the part index, never the render mesh), with the rig's guide friction.
  if (s.frame) {
    for (const FramePart& part : s.frame->parts) {
      if (!part.guide) continue;
      for (const CollisionBoxDesc& box : part.boxes) {
        guide_shapes.push_back(std::make_unique<btBoxShape>(
            btVector3(0.5 * box.size[0], 0.5 * box.size[1], 0.5 * box.size[2])));
        auto object = std::make_unique<btCollisionObject>();
        object->setCollisionShape(guide_shapes.back().get());
        object->setWorldTransform(btTransform(
            btQuaternion::getIdentity(),
            btVector3(part.position[0] + box.center[0], part.position[1] + box.center[1],
                      part.position[2] + box.center[2])));
        object->setFriction(0.0);  // per contact point (ContactFriction)
        object->setRestitution(0.0);
        world.addCollisionObject(object.get());
        guides.push_back(std::move(object));
      }
    }
  }
}

void RigWorld::Impl::add_plate() {
  const CompiledRig& s = rig;
  const PlateMass& mass = rig.plate;
  // The plate: its centre of mass is the body's origin. For collision it is a box whose bottom
  // face lies h_c below the centre of mass (the contact line), as long and wide as the plate;
  // only that face and the sides ever touch anything. Mass and pitch inertia come from the
  // parts (slab, payload, magnets), not from the box.
  const PlateDesc& p = s.plate_desc;
  plate_shape = std::make_unique<btBoxShape>(btVector3(0.5 * p.length, 0.5 * p.width, mass.h_c));
  // Inertia about x and z does not act (the motion is planar) but must be positive.
  const btVector3 inertia(mass.inertia_pitch, mass.inertia_pitch, mass.inertia_pitch);
  btRigidBody::btRigidBodyConstructionInfo ci(mass.mass, nullptr, plate_shape.get(), inertia);
  ci.m_startWorldTransform =
      btTransform(btQuaternion::getIdentity(), btVector3(p.offset, 0, mass.h_c));
  ci.m_friction = 0.0;  // per contact point (ContactFriction)
  ci.m_restitution = 0.0;
  ci.m_rollingFriction = 0.0;
  ci.m_spinningFriction = 0.0;
  ci.m_linearDamping = 0.0;
  ci.m_angularDamping = 0.0;
  plate = std::make_unique<btRigidBody>(ci);
  plate->setActivationState(DISABLE_DEACTIVATION);
  if (guides.empty() && s.rollers.skew != 0.0) {
    // No guides and skewed axes: the plate also drifts along y with the rollers' surfaces.
    plate->setLinearFactor(btVector3(1, 1, 1));
    plate->setAngularFactor(btVector3(0, 1, 0));
  } else if (guides.empty()) {
    // No guides (the minimal scene): the plate moves in the x-z plane and pitches about y.
    plate->setLinearFactor(btVector3(1, 0, 1));
    plate->setAngularFactor(btVector3(0, 1, 0));
  } else {
    // The guides hold it sideways: free along y and in yaw. It does not roll about x: the
    // rollers' line contact prevents that, which one point contact per roller cannot.
    plate->setLinearFactor(btVector3(1, 1, 1));
    plate->setAngularFactor(btVector3(0, 1, 1));
  }
  plate->setLinearVelocity(btVector3(p.velocity, guides.empty() ? 0.0 : p.sideways_velocity, 0));
  if (s.rollers.runout > 0.0) rest_on_off_centre_rollers();
  world.addRigidBody(plate.get());
}

void RigWorld::Impl::before_solve(const btContactSolverInfo& info) {
  friction->before_solve(dispatcher);
  std::array<RollerContactPoint, 2> points{};
  const int n = dispatcher.getNumManifolds();
  for (int m = 0; m < n; ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const bool plate_first = manifold->getBody0() == plate.get();
    const btCollisionObject* other = plate_first ? manifold->getBody1() : manifold->getBody0();
    if (!plate_first && manifold->getBody1() != plate.get()) continue;
    for (std::size_t i = 0; i < 2; ++i) {
      if (other != rollers[i].get()) continue;
      if (manifold->getNumContacts() != 1 || points[i].point != nullptr) return;
      points[i] = {&manifold->getContactPoint(0), plate_first, rollers[i].get()};
    }
  }
  warm_start_roller_contacts(*plate, points, dt, info, solver);
}

RigWorld::Impl::~Impl() {
  world.removeRigidBody(plate.get());
  for (auto& g : guides) world.removeCollisionObject(g.get());
  for (auto& r : rollers) world.removeRigidBody(r.get());
}

std::array<RollerContact, 2> RigWorld::Impl::measure_contacts(
    std::array<ContactFriction::RollerImpulses, 2>& impulses) const {
  std::array<RollerContact, 2> out{};
  std::array<double, 2> deepest{};
  std::array<bool, 2> seen{};
  const int n = dispatcher.getNumManifolds();
  for (int m = 0; m < n; ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    bool plate_first = false;
    const int roller = plate_manifold_roller(*manifold, plate.get(), roller_bodies(), plate_first);
    if (roller < 0) continue;
    const auto i = static_cast<std::size_t>(roller);
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      const btManifoldPoint& pt = manifold->getContactPoint(k);
      // The normal points from body1 to body0; we want forces on the plate.
      const double sign = plate_first ? 1.0 : -1.0;
      const btVector3 normal = sign * pt.m_normalWorldOnB;
      const btVector3 impulse = normal * pt.getAppliedImpulse() +
                                sign * pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                                sign * pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
      out[i].touching = out[i].touching || pt.getDistance() <= 0.0 || pt.getAppliedImpulse() > 0.0;
      out[i].normal_force += impulse.z() / dt;
      out[i].friction_force += impulse.x() / dt;
      const double distance = pt.getDistance();
      if (!seen[i] || -distance > deepest[i]) {
        seen[i] = true;
        // Bullet's normal row aims at -distance / dt for a point still apart, and pushes a
        // penetrating one out at erp2 depth / dt (btSequentialImpulseConstraintSolver).
        deepest[i] = -distance;
        const btVector3& at = plate_first ? pt.getPositionWorldOnA() : pt.getPositionWorldOnB();
        out[i].point_x = at.x();
        out[i].point_z = at.z();
        // Relative to the roller's surface: a roller off its shaft moves its axis (run-out),
        // and the surface's normal speed is the axis's (omega x r is along the surface).
        out[i].normal_speed_target = -distance / dt * (distance > 0.0 ? 1.0 : contact_erp) +
                                     normal.dot(rollers[i]->getLinearVelocity());
      }
      out[i].penetration = std::max(out[i].penetration, -distance);
      impulses[i].add(pt);
    }
  }
  // The plate's bottom face (h_c below its centre of mass along its own z axis) above each
  // roller's surface: the distance from the tube's axis to that plane, less the radius.
  const btTransform& body = plate->getCenterOfMassTransform();
  const btVector3 up = body.getBasis().getColumn(2);
  const btVector3 bottom = body.getOrigin() - up * rig.plate.h_c;
  for (std::size_t i = 0; i < 2; ++i) {
    const double above = (bottom - rollers[i]->getWorldTransform().getOrigin()).dot(up);
    out[i].gap = std::max(above - rig.roller_radii[i], 0.0);
  }
  return out;
}

RigWorld::RigWorld(const CompiledRig& rig) : impl_(std::make_unique<Impl>(rig, nullptr)) {}
RigWorld::RigWorld(const Scene& scene) {
  auto rig = compile_rig_shared(scene);
  impl_ = std::make_unique<Impl>(*rig, rig);
}
RigWorld::~RigWorld() = default;

void RigWorld::step() {
  const CompiledRig& rig = impl_->rig;
  const double t_next = static_cast<double>(impl_->steps + 1) * impl_->dt;
  if (impl_->drivetrain) {
    // The train advances under the torques the plate's friction put on the rollers in the last
    // step: -a F_i about y for a friction force F_i (along x) on the plate at roller i's top.
    // The most the plate's static friction holds the rollers with, seen at the motor.
    const std::array<RollerContact, 2>& last = impl_->contacts;
    const double a = impl_->rig.rollers.radius;
    const double duty = rig.duty_ramp ? rig.duty_ramp->at(t_next) : rig.drive->parts.motor.duty;
    const std::vector<double>& u = rig.drive->shaft_ratios;
    const double holding = rig.friction.mu_s * a *
                           (std::fabs(u[0]) * std::max(last[0].normal_force, 0.0) +
                            std::fabs(u[1]) * std::max(last[1].normal_force, 0.0));
    impl_->drivetrain->advance(
        impl_->dt, {-a * last[0].friction_force, -a * last[1].friction_force}, duty, holding);
    impl_->roller_omega = impl_->drivetrain->roller_speeds();
  } else if (rig.roller_speed_ramp) {
    // The ideal drive's scheduled speed at the step's end (the speed the solver holds the
    // rollers at over the step; what roller_speeds() reads after it).
    const double sense = impl_->rig.rollers.sense == RollerSense::kInward ? 1.0 : -1.0;
    impl_->roller_omega = {sense * rig.roller_speed_ramp->at(t_next),
                           -sense * rig.roller_speed_ramp_roller_1->at(t_next)};
  }
  if (rig.warming) {
    // Warming rollers: the law's coefficients scaled with mu_k at the step's middle.
    const double scale = rig.warming->mu_k(t_next - 0.5 * impl_->dt) / rig.warming->mu_k_start();
    FrictionLaw law = rig.friction;
    law.mu_k *= scale;
    law.mu_s *= scale;
    impl_->friction->set_law(law);
  }
  impl_->solver.m_analyticsData.m_numIterationsUsed = 0;
  impl_->world.stepSimulation(impl_->dt, 0);
  for (std::size_t i = 0; i < 2; ++i) impl_->roller_angle[i] += impl_->roller_omega[i] * impl_->dt;
  std::array<ContactFriction::RollerImpulses, 2> impulses{};
  impl_->contacts = impl_->measure_contacts(impulses);
  impl_->friction->after_step(impulses);
  for (std::size_t i = 0; i < 2; ++i) impl_->contacts[i].stuck = impl_->friction->stuck()[i];
  ++impl_->steps;
}

double RigWorld::time() const {
  return static_cast<double>(impl_->steps) * impl_->dt;
}

int RigWorld::solver_iterations_used() const {
  return impl_->solver.m_analyticsData.m_numIterationsUsed;
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
  s.y = t.getOrigin().y();
  s.yaw = std::atan2(ex.y(), ex.x());
  s.vx = b.getLinearVelocity().x();
  s.vz = b.getLinearVelocity().z();
  s.pitch_rate = b.getAngularVelocity().y();
  return s;
}

std::array<RollerContact, 2> RigWorld::contacts() const {
  return impl_->contacts;
}

std::array<double, 2> RigWorld::roller_speeds() const {
  return impl_->roller_omega;
}

std::array<double, 2> RigWorld::roller_body_speeds() const {
  return {impl_->rollers[0]->getAngularVelocity().y(), impl_->rollers[1]->getAngularVelocity().y()};
}

std::array<double, 2> RigWorld::roller_angles() const {
  return impl_->roller_angle;
}

std::array<double, 2> RigWorld::roller_surface_speeds() const {
  const std::array<double, 2>& a = impl_->rig.roller_radii;
  const std::array<double, 2> omega = roller_speeds();
  return {omega[0] * a[0], omega[1] * a[1]};
}

std::optional<DriveState> RigWorld::drive() const {
  if (!impl_->drivetrain) return std::nullopt;
  const Drivetrain& d = *impl_->drivetrain;
  DriveState state;
  state.motor_speed = d.motor_speed();
  state.motor_torque = d.motor_torque();
  state.roller_speeds = d.roller_speeds();
  return state;
}

std::vector<ShaftState> RigWorld::shafts() const {
  std::vector<ShaftState> out;
  if (!impl_->drivetrain) return out;
  const Drivetrain& d = *impl_->drivetrain;
  for (std::size_t i = 0; i < d.layout().shafts.size(); ++i)
    out.push_back({d.angle(static_cast<int>(i)), d.speed(static_cast<int>(i))});
  return out;
}

const CompiledRig& RigWorld::rig() const {
  return impl_->rig;
}

}  // namespace fl
