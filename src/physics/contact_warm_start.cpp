#include "physics/contact_warm_start.hpp"

#include <cmath>

namespace fl {
namespace {

// The plate's slip against a roller below this speed [m/s] gives its friction no direction.
constexpr double kNoSlip = 1e-9;

}  // namespace

std::optional<std::array<double, 2>> resting_normal_impulses(
    const btRigidBody& plate, const std::array<RollerContactPoint, 2>& contacts, double time_step,
    double erp) {
  // Per contact: the lever from the plate's centre of mass, the unit normal pushing the plate,
  // the impulse's direction per unit normal impulse (normal plus sliding friction), and the
  // normal speed still to be made up by the step's end.
  std::array<btVector3, 2> lever, normal, direction;
  std::array<double, 2> wanted{};
  const btVector3 external = plate.getTotalForce() * plate.getInvMass() * time_step;
  for (std::size_t i = 0; i < 2; ++i) {
    const btManifoldPoint& pt = *contacts[i].point;
    const bool a = contacts[i].plate_first;
    const btVector3& at = a ? pt.getPositionWorldOnA() : pt.getPositionWorldOnB();
    normal[i] = a ? pt.m_normalWorldOnB : -pt.m_normalWorldOnB;
    lever[i] = at - plate.getCenterOfMassPosition();
    const btRigidBody& roller = *contacts[i].roller;
    const btVector3 relative =
        plate.getVelocityInLocalPoint(lever[i]) -
        roller.getVelocityInLocalPoint(at - roller.getCenterOfMassPosition());
    // The slip Bullet's friction row takes its direction from: the velocities at the step's start
    // with the step's external impulse (a tilted rig's gravity has a part along the plate).
    const btVector3 moving = relative + external;
    const btVector3 slip = moving - normal[i] * normal[i].dot(moving);
    const double slip_speed = slip.length();
    if (!(slip_speed > kNoSlip)) return std::nullopt;
    direction[i] = normal[i] - pt.m_combinedFriction * slip / slip_speed;
    const double distance = pt.getDistance();
    const double aim = -distance / time_step * (distance > 0.0 ? 1.0 : erp);
    wanted[i] = aim - normal[i].dot(moving);
  }
  // Speed change along normal i per unit impulse at contact j, as the solver moves the plate
  // (its linear and angular factors hold it to its plane).
  const auto response = [&](std::size_t i, std::size_t j) {
    const btVector3 dv = direction[j] * plate.getInvMass() * plate.getLinearFactor();
    const btVector3 dw = (plate.getInvInertiaTensorWorld() * lever[j].cross(direction[j])) *
                         plate.getAngularFactor();
    return normal[i].dot(dv + dw.cross(lever[i]));
  };
  const double a00 = response(0, 0), a01 = response(0, 1);
  const double a10 = response(1, 0), a11 = response(1, 1);
  const double det = a00 * a11 - a01 * a10;
  if (!(det > 0.0) || !(a00 > 0.0) || !(a11 > 0.0)) return std::nullopt;
  const std::array<double, 2> impulse{(wanted[0] * a11 - a01 * wanted[1]) / det,
                                      (a00 * wanted[1] - a10 * wanted[0]) / det};
  if (!(impulse[0] > 0.0) || !(impulse[1] > 0.0)) return std::nullopt;
  return impulse;
}

void RollerContactSolver::start_friction_at(const std::array<RollerContactPoint, 2>& contacts) {
  for (std::size_t i = 0; i < 2; ++i) friction_started_[i] = contacts[i].point;
}

void RollerContactSolver::convertContacts(btPersistentManifold** manifolds, int count,
                                          const btContactSolverInfo& info) {
  btSequentialImpulseConstraintSolver::convertContacts(manifolds, count, info);
  const std::array<const btManifoldPoint*, 2> started = friction_started_;
  friction_started_ = {};
  if (started[0] == nullptr && started[1] == nullptr) return;
  for (int c = 0; c < m_tmpSolverContactConstraintPool.size(); ++c) {
    const btSolverConstraint& contact = m_tmpSolverContactConstraintPool[c];
    const auto* point = static_cast<const btManifoldPoint*>(contact.m_originalContactPoint);
    if (point == nullptr || (point != started[0] && point != started[1])) continue;
    // As the solver applies a row's impulse (resolveSingleConstraintRowGeneric), and as it warm
    // starts a normal row (setupContactConstraint).
    btSolverConstraint& friction =
        m_tmpSolverContactFrictionConstraintPool[contact.m_frictionIndex];
    friction.m_appliedImpulse = point->m_appliedImpulseLateral1 * info.m_warmstartingFactor;
    btSolverBody& a = m_tmpSolverBodyPool[friction.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[friction.m_solverBodyIdB];
    a.internalApplyImpulse(friction.m_contactNormal1 * a.internalGetInvMass(),
                           friction.m_angularComponentA, friction.m_appliedImpulse);
    b.internalApplyImpulse(friction.m_contactNormal2 * b.internalGetInvMass(),
                           friction.m_angularComponentB, friction.m_appliedImpulse);
  }
}

bool warm_start_roller_contacts(const btRigidBody& plate,
                                const std::array<RollerContactPoint, 2>& contacts, double time_step,
                                const btContactSolverInfo& info, RollerContactSolver& solver) {
  if (!(info.m_solverMode & SOLVER_USE_WARMSTARTING) || !(info.m_warmstartingFactor > 0.0))
    return false;
  for (const RollerContactPoint& c : contacts)
    if (c.point == nullptr) return false;
  const std::optional<std::array<double, 2>> impulse =
      resting_normal_impulses(plate, contacts, time_step, info.m_erp2);
  if (!impulse) return false;
  // The sliding friction with it: Bullet's friction row for a sliding point runs along the
  // tangential velocity of body 0 relative to body 1, so the friction that opposes the slip is a
  // negative impulse along it, whichever body the plate is.
  for (std::size_t i = 0; i < 2; ++i) {
    btManifoldPoint& pt = *contacts[i].point;
    pt.m_appliedImpulse = (*impulse)[i] / info.m_warmstartingFactor;
    pt.m_appliedImpulseLateral1 = -pt.m_combinedFriction * pt.m_appliedImpulse;
    pt.m_appliedImpulseLateral2 = 0.0;
  }
  solver.start_friction_at(contacts);
  return true;
}

}  // namespace fl
