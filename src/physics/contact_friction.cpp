#include "physics/contact_friction.hpp"

#include <algorithm>
#include <cmath>

#include "physics/plate_manifold.hpp"

namespace fl {
namespace {

// A friction impulse below this fraction of its limit is not saturated: the contact is stuck.
constexpr double kSaturation = 1.0 - 1e-9;

// The plate's direction of motion (x) in the contact plane of normal n, and the second direction.
void stuck_directions(const btVector3& n, btVector3& along, btVector3& across) {
  along = btVector3(1, 0, 0) - n * n.x();
  along.normalize();
  across = n.cross(along);
  across.normalize();
}

}  // namespace

ContactFriction::ContactFriction(const FrictionLaw& law, double guide_friction,
                                 const btRigidBody* plate,
                                 std::array<const btRigidBody*, 2> rollers)
    : law_(law),
      guide_friction_(guide_friction),
      plate_(plate),
      rollers_(rollers),
      slip_dependent_(law.depends_on_slip()) {}

void ContactFriction::before_solve(btDispatcher& dispatcher) {
  const int manifolds = dispatcher.getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    bool plate_first = false;
    const int who = plate_manifold_roller(*manifold, plate_, rollers_, plate_first);
    if (who == -2) continue;
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      btManifoldPoint& pt = manifold->getContactPoint(k);
      if (who == -1) {
        pt.m_combinedFriction = guide_friction_;
        continue;
      }
      const auto i = static_cast<std::size_t>(who);
      const btVector3& n = pt.m_normalWorldOnB;
      if (stuck_[i]) {
        double limit = law_.mu_s;
        // When the ratio |F|/N, extrapolated from the last two steps, crosses mu_s: the contact
        // breaks there, and this step's limit is blended by the share of its impulse that comes
        // before the crossing. The semi-implicit Euler step is a leapfrog: the impulse solved at
        // this step's positions stands for the half steps either side of them, from half a step
        // after the last positions to one and a half, so that is the window the crossing is
        // placed in (counting from the step's start instead broke the stick half a step late).
        if (stuck_steps_[i] >= 2) {
          const double rise = ratio_now_[i] - ratio_before_[i];  // per step
          if (rise > 0.0) {
            const double crossing = (law_.mu_s - ratio_now_[i]) / rise;  // steps after the last
            const double before = std::clamp(crossing - 0.5, 0.0, 1.0);
            limit = before * law_.mu_s + (1.0 - before) * law_.kinetic(0.0);
          }
        }
        pt.m_combinedFriction = limit;
        stuck_directions(n, pt.m_lateralFrictionDir1, pt.m_lateralFrictionDir2);
        pt.m_contactMotion1 = 0;
        pt.m_contactMotion2 = 0;
        pt.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
      } else {
        pt.m_contactPointFlags &= ~BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
        pt.m_combinedFriction = law_.mu_k;
      }
      if (!slip_dependent_) continue;
      // The plate's velocity relative to the roller's surface at the point, in the contact plane.
      const btRigidBody& roller = *rollers_[i];
      const btVector3& at = plate_first ? pt.getPositionWorldOnA() : pt.getPositionWorldOnB();
      const btVector3 relative =
          plate_->getVelocityInLocalPoint(at - plate_->getCenterOfMassPosition()) -
          roller.getVelocityInLocalPoint(at - roller.getCenterOfMassPosition());
      const btVector3 slip = relative - n * n.dot(relative);
      if (!stuck_[i]) {
        // The slip at mid-step, extrapolated from this step's start and the last one's.
        const btVector3 mid = has_slip_before_[i] ? 1.5 * slip - 0.5 * slip_now_[i] : slip;
        pt.m_combinedFriction = law_.kinetic(mid.length());
      }
      slip_now_[i] = slip;
      has_slip_before_[i] = true;
    }
  }
}

void ContactFriction::RollerImpulses::add(const btManifoldPoint& pt) {
  const double normal = pt.getAppliedImpulse();
  if (!(normal > 0.0)) return;
  const double friction = std::hypot(pt.m_appliedImpulseLateral1, pt.m_appliedImpulseLateral2);
  pressed = true;
  saturated = saturated || !(friction < kSaturation * pt.m_combinedFriction * normal);
  ratio = std::max(ratio, friction / normal);
}

void ContactFriction::after_step(const std::array<RollerImpulses, 2>& impulses) {
  for (std::size_t i = 0; i < 2; ++i) {
    const RollerImpulses& r = impulses[i];
    const bool stuck = r.pressed && !r.saturated;
    if (stuck) {
      ratio_before_[i] = stuck_[i] ? ratio_now_[i] : r.ratio;
      ratio_now_[i] = r.ratio;
      ++stuck_steps_[i];
    } else {
      stuck_steps_[i] = 0;
    }
    stuck_[i] = stuck;
  }
}

}  // namespace fl
