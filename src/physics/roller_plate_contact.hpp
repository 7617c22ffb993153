// A roller (a sphere) against the plate (a box): their closest points in closed form. Bullet's
// general convex test (GJK) finds the same contact by iteration and took about a quarter of a
// step's time; this one reports exactly what GJK reports for the pair (the normal from the box's
// core toward the sphere's centre, the point on body B's rounded surface, the distance between
// the surfaces, contacts kept out to the manifold's breaking threshold), in a few operations.
// Bullet's own sphere-box test (compiled out of Bullet by default, "buggy") reports less: a plate
// on rollers with run-out stopped hopping with it (docs/physics.md).
#pragma once

#include <btBulletCollisionCommon.h>

namespace fl {

// Has `dispatcher` use the closed-form test for every sphere-box pair, whichever comes first.
// Call before any pair of those shapes exists.
void use_closed_form_sphere_box_contact(btCollisionDispatcher& dispatcher);

// The contact the test finds for a sphere (centre and radius in world space) and a box (its
// transform, half extents without margin, margin), as seen from the box: the unit normal from the
// box toward the sphere (world), the point on the box's surface nearest the sphere (world), and
// the distance between the surfaces (< 0: they overlap). For tests and for the pair's algorithm.
struct SphereBoxContact {
  btVector3 normal_on_box;
  btVector3 point_on_box;
  btVector3 point_on_sphere;
  btScalar distance = 0;
};
SphereBoxContact sphere_box_contact(const btVector3& centre, btScalar radius,
                                    const btTransform& box, const btVector3& half_extents,
                                    btScalar box_margin);

}  // namespace fl
