// The rig's friction, applied per contact point and per step in one place: after Bullet's
// collision detection and before its solver (FrictionWorld::solveConstraints), every point
// between the plate and a roller gets the friction law's coefficient for its slip speed, or the
// static limit while the contact is stuck; every point between the plate and a guide tower gets
// the guides' own friction. No process-global state: Bullet's combined friction is overwritten
// per point.
//
// Stuck or slipping is decided by saturation after each step (docs/physics.md): a contact is
// stuck when its normal impulse is positive and its friction impulse stays below the limit. A
// stuck contact's friction acts along the plate's direction of motion (x, in the contact plane),
// set explicitly: Bullet would otherwise pick the roller's axis for a contact with no tangential
// speed in a z-up world, and the stick would not hold.
//
// Second order in the step: a slipping contact's coefficient is evaluated at the mid-step slip
// velocity extrapolated from the last two steps; a stuck contact whose friction ratio |F|/N is
// about to cross mu_s breaks inside the step, its limit blended between mu_s and the kinetic
// value by the fraction of the step before the crossing.
#pragma once

#include <array>

#include <btBulletDynamicsCommon.h>

#include "core/friction_law.hpp"

namespace fl {

class ContactFriction {
 public:
  // The plate, the two rollers (index 0 at x = -l/2) and the guides' friction coefficient.
  ContactFriction(const FrictionLaw& law, double guide_friction, const btRigidBody* plate,
                  std::array<const btRigidBody*, 2> rollers);

  // Before the solver: sets every plate-roller and plate-guide point's combined friction (and a
  // stuck contact's friction directions).
  void before_solve(btDispatcher& dispatcher);
  // What the solver did at one roller's contact in the last step, gathered point by point (by the
  // world's one read of the contact manifolds after each step).
  struct RollerImpulses {
    bool pressed = false;    // a point with a positive normal impulse
    bool saturated = false;  // a pressed point whose friction impulse reached its limit
    double ratio = 0.0;      // the largest |friction impulse| / normal impulse
    void add(const btManifoldPoint& point);
  };
  // After the step: decides from the solver's impulses which roller contacts are stuck.
  void after_step(const std::array<RollerImpulses, 2>& impulses);

  // The law from the next step on (rollers whose friction changes over the run, as they warm).
  void set_law(const FrictionLaw& law) { law_ = law; }

  // Whether the plate is stuck to each roller after the last step.
  const std::array<bool, 2>& stuck() const { return stuck_; }

 private:
  FrictionLaw law_;
  double guide_friction_;
  const btRigidBody* plate_;
  std::array<const btRigidBody*, 2> rollers_;
  bool slip_dependent_;

  std::array<bool, 2> stuck_{};
  // Per roller contact: the slip velocity (plate relative to the roller's surface, in the
  // contact plane) at the start of the last step (slip-dependent laws only), and the friction
  // ratio |F|/N of the last two stuck steps.
  std::array<btVector3, 2> slip_now_{};
  std::array<bool, 2> has_slip_before_{};
  std::array<double, 2> ratio_now_{};
  std::array<double, 2> ratio_before_{};
  std::array<int, 2> stuck_steps_{};
};

}  // namespace fl
