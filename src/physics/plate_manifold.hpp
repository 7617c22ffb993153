// Which of the rig's bodies a Bullet contact manifold joins to the plate (internal to
// src/physics): the friction law sets its points' coefficients by it, the solver's start finds
// the roller contacts by it, and the step reads the rollers' forces by it.
#pragma once

#include <array>

#include <btBulletDynamicsCommon.h>

namespace fl {

// Roller 0 or 1 when the manifold joins that roller to the plate, -1 when it joins another body
// to the plate (a guide), -2 when the plate is not in it. `plate_first`: whether the plate is the
// manifold's body 0 (Bullet's normal points from body 1 to body 0).
inline int plate_manifold_roller(const btPersistentManifold& manifold,
                                 const btCollisionObject* plate,
                                 const std::array<const btRigidBody*, 2>& rollers,
                                 bool& plate_first) {
  const btCollisionObject* a = manifold.getBody0();
  const btCollisionObject* b = manifold.getBody1();
  if (a != plate && b != plate) return -2;
  plate_first = a == plate;
  const btCollisionObject* other = plate_first ? b : a;
  for (int i = 0; i < 2; ++i)
    if (other == rollers[static_cast<std::size_t>(i)]) return i;
  return -1;
}

}  // namespace fl
