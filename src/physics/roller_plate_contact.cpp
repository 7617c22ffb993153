#include "physics/roller_plate_contact.hpp"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include <algorithm>
#include <cmath>
#include <new>

namespace fl {

SphereBoxContact sphere_box_contact(const btVector3& centre, btScalar radius,
                                    const btTransform& box, const btVector3& half_extents,
                                    btScalar box_margin) {
  // In the box's frame: the point of the box's core (the box less its margin) nearest the centre.
  const btVector3 c = box.invXform(centre);
  btVector3 nearest(std::clamp(c.x(), -half_extents.x(), half_extents.x()),
                    std::clamp(c.y(), -half_extents.y(), half_extents.y()),
                    std::clamp(c.z(), -half_extents.z(), half_extents.z()));
  btVector3 normal = c - nearest;
  btScalar core_distance = normal.length();
  if (core_distance > 0) {
    normal /= core_distance;
  } else {
    // The centre inside the core (a penetration deeper than both margins, which GJK hands to
    // EPA): out through the nearest face.
    int axis = 0;
    btScalar least = half_extents[0] - std::fabs(c[0]);
    for (int k = 1; k < 3; ++k) {
      const btScalar depth = half_extents[k] - std::fabs(c[k]);
      if (depth < least) {
        least = depth;
        axis = k;
      }
    }
    normal.setZero();
    normal[axis] = c[axis] < 0 ? -1 : 1;
    nearest[axis] = normal[axis] * half_extents[axis];
    core_distance = -least;
  }
  SphereBoxContact out;
  out.normal_on_box = box.getBasis() * normal;
  out.point_on_box = box * (nearest + normal * box_margin);
  out.point_on_sphere = centre - out.normal_on_box * radius;
  out.distance = core_distance - radius - box_margin;
  return out;
}

namespace {

// The pair's algorithm, in the form of Bullet's convex-convex one: its own manifold made on the
// first call, the contact added (btManifoldResult keeps it only within the breaking threshold),
// the manifold refreshed.
class SphereBoxAlgorithm final : public btActivatingCollisionAlgorithm {
 public:
  SphereBoxAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                     const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1)
      : btActivatingCollisionAlgorithm(info, body0, body1), manifold_(info.m_manifold) {}

  ~SphereBoxAlgorithm() override {
    if (own_manifold_ && manifold_ != nullptr) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, const btDispatcherInfo& /*info*/,
                        btManifoldResult* result) override {
    if (manifold_ == nullptr) {
      manifold_ =
          m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
      own_manifold_ = true;
    }
    result->setPersistentManifold(manifold_);
    const bool sphere_first = body0->getCollisionShape()->getShapeType() == SPHERE_SHAPE_PROXYTYPE;
    const btCollisionObjectWrapper* sphere = sphere_first ? body0 : body1;
    const btCollisionObjectWrapper* box = sphere_first ? body1 : body0;
    const auto* ball = static_cast<const btSphereShape*>(sphere->getCollisionShape());
    const auto* slab = static_cast<const btBoxShape*>(box->getCollisionShape());
    // As GJK sees them: a sphere is its centre with its radius as margin, a box its core with
    // its margin.
    const SphereBoxContact contact = sphere_box_contact(
        sphere->getWorldTransform().getOrigin(), ball->getMargin(), box->getWorldTransform(),
        slab->getHalfExtentsWithoutMargin(), slab->getMargin());
    // Bullet's convention: the normal on body B, pointing toward body A, and the point on B.
    if (sphere_first)
      result->addContactPoint(contact.normal_on_box, contact.point_on_box, contact.distance);
    else
      result->addContactPoint(-contact.normal_on_box, contact.point_on_sphere, contact.distance);
    if (own_manifold_) result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject* /*body0*/, btCollisionObject* /*body1*/,
                                 const btDispatcherInfo& /*info*/,
                                 btManifoldResult* /*result*/) override {
    return 1;  // no continuous collision (as for every pair in the rig's world)
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_ != nullptr && own_manifold_) manifolds.push_back(manifold_);
  }

 private:
  btPersistentManifold* manifold_;
  bool own_manifold_ = false;
};

struct SphereBoxCreate final : public btCollisionAlgorithmCreateFunc {
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SphereBoxAlgorithm));
    return new (memory) SphereBoxAlgorithm(info, body0, body1);
  }
};

}  // namespace

void use_closed_form_sphere_box_contact(btCollisionDispatcher& dispatcher) {
  // Stateless, shared by every world.
  static SphereBoxCreate create;
  dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, &create);
  dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &create);
}

}  // namespace fl
