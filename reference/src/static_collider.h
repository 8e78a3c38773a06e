#pragma once
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <LinearMath/btDefaultMotionState.h>

#include <memory>
#include <vector>

#include "mysim/collider.h"

namespace reference {

// A mysim collider as a static (mass 0) Bullet rigid body with its friction, added to a world on
// construction and removed on destruction (so it must die before the world does). Soft bodies
// meet it through Bullet's sparse signed-distance field, which only samples convex shapes
// (btSparseSdf::DistanceToShape): every shape is built from convex ones, the plane as a box far
// larger than any scene whose face is the plane.
class StaticCollider {
 public:
  StaticCollider(btDiscreteDynamicsWorld& world, const mysim::Collider& collider);
  ~StaticCollider();
  StaticCollider(const StaticCollider&) = delete;
  StaticCollider& operator=(const StaticCollider&) = delete;

 private:
  btDiscreteDynamicsWorld& world_;
  std::unique_ptr<btCollisionShape> shape_;
  btDefaultMotionState motion_;
  std::unique_ptr<btRigidBody> body_;
};

// Every collider of a model, in a world.
std::vector<std::unique_ptr<StaticCollider>> addColliders(
    btDiscreteDynamicsWorld& world, const std::vector<mysim::Collider>& colliders);

// The sparse SDF's voxel size (m): fine enough for the smallest curved feature (a sphere's
// radius / 10, as measured good on the cloth on a sphere; a box's smallest half-side / 5, so its
// edges round off over a fifth of it), 0.25 m (Bullet's default) where nothing is curved (the
// field of a flat face is linear, which trilinear interpolation reproduces at any voxel size).
double sdfVoxelSize(const std::vector<mysim::Collider>& colliders);
// Whether any collider has friction: then the soft body's kDF is 1, so kDF x the body's friction
// is the collider's coefficient (frictionless scenes keep the settings they always had).
bool anyFriction(const std::vector<mysim::Collider>& colliders);
// The soft body's collision margin (m): the largest collider margin, at least 0.1 mm (Bullet's
// contact needs a positive margin); 1 mm without colliders.
double softBodyMargin(const std::vector<mysim::Collider>& colliders);

}  // namespace reference
