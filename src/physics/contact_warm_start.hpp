// Where Bullet's solver starts each step on the plate's two roller contacts. The
// sequential-impulse solver starts each contact's normal impulse from the last step's times a
// factor (0.85, warm starting), a new contact's from zero, and (Bullet 3.24) every friction row
// from zero. The two contacts share the plate's weight through its pitch, and on a long plate
// between close rollers that split is ill-conditioned: a 300 mm plate on rollers 40 mm apart has
// a 2 x 2 contact matrix whose Gauss-Seidel iterations shrink an error by about 0.8 each, so from
// Bullet's start 10 iterations leave a normal force off by several 1e-4 of the weight. The run's
// solver check (lab/run/solver_convergence.hpp) then finds the step unconverged and the whole run
// starts again at twice the iterations, sometimes four times: in a sweep of materials and
// spacings on such a plate, two points in five did. Starting both normal impulses and their
// sliding friction at the balance the step asks for (exact while both contacts slide) leaves the
// solver nothing to undo; the answer stays the solver's own (it still iterates, and the check
// still judges it), only its starting guess moves.
#pragma once

#include <array>
#include <optional>

#include <btBulletDynamicsCommon.h>

namespace fl {

// One roller's contact with the plate: its single manifold point, whether the plate is the
// manifold's body 0, and the roller.
struct RollerContactPoint {
  btManifoldPoint* point = nullptr;
  bool plate_first = true;
  const btRigidBody* roller = nullptr;
};

// The two normal impulses [N s] that bring both contact points to the normal speed the solver aims
// for at the step's end (closing a gap, or pushing a penetration out at erp depth / dt, as
// btSequentialImpulseConstraintSolver does), with each contact's friction sliding against the
// slip Bullet directs its friction row by (the step's start plus the step's external impulse;
// mu = the point's combined friction), under the plate's
// external force over the step (gravity): the 2 x 2 linear balance of the plate's speeds at the
// points. Nullopt when there is no such balance with both impulses positive (a plate lifting off a
// roller, a contact with no slip to give its friction a direction, a singular balance).
std::optional<std::array<double, 2>> resting_normal_impulses(
    const btRigidBody& plate, const std::array<RollerContactPoint, 2>& contacts, double time_step,
    double erp);

// Bullet's sequential-impulse solver, which also starts the friction rows of chosen contact
// points from their points' lateral impulses. Bullet 3.24 starts every friction row from zero
// (btSequentialImpulseConstraintSolver::setFrictionConstraintImpulse), so a normal impulse started
// at its balance is pulled off it in the first iterations by its friction arriving late: the
// friction's moment on the plate shifts the split. The chosen points are those warm_start_roller_
// contacts set, for the next solve only.
class RollerContactSolver final : public btSequentialImpulseConstraintSolver {
 public:
  // The points whose friction rows start from their m_appliedImpulseLateral1 times the warm-
  // starting factor in the next solve; forgotten after it.
  void start_friction_at(const std::array<RollerContactPoint, 2>& contacts);

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count,
                       const btContactSolverInfo& info) override;

 private:
  std::array<const btManifoldPoint*, 2> friction_started_{};
};

// Sets both points' applied impulses so that the solver's warm start (the applied impulse times
// `info`'s warm-starting factor) is the balance above, the sliding friction with it, when the
// balance exists; otherwise leaves them as they are (the solver starts from the last step's).
// With the balance, tells `solver` to start the points' friction rows there too. Returns whether it
// set them.
bool warm_start_roller_contacts(const btRigidBody& plate,
                                const std::array<RollerContactPoint, 2>& contacts, double time_step,
                                const btContactSolverInfo& info, RollerContactSolver& solver);

}  // namespace fl
