#pragma once
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <LinearMath/btDefaultMotionState.h>

#include <memory>

#include "mysim/sphere_collider.h"

namespace reference {

// mysim's sphere as a static (mass 0), frictionless Bullet rigid body, added to a world on
// construction and removed on destruction (so it must die before the world does).
class StaticSphere {
 public:
  StaticSphere(btDiscreteDynamicsWorld& world, const mysim::Sphere& sphere);
  ~StaticSphere();
  StaticSphere(const StaticSphere&) = delete;
  StaticSphere& operator=(const StaticSphere&) = delete;

 private:
  btDiscreteDynamicsWorld& world_;
  btSphereShape shape_;
  btDefaultMotionState motion_;
  std::unique_ptr<btRigidBody> body_;
};

}  // namespace reference
