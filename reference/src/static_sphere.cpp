#include "static_sphere.h"

namespace reference {

StaticSphere::StaticSphere(btDiscreteDynamicsWorld& world, const mysim::Sphere& sphere)
    : world_(world),
      shape_(sphere.radius),
      motion_(btTransform(btMatrix3x3::getIdentity(),
                          btVector3(sphere.center.x(), sphere.center.y(), sphere.center.z()))) {
  body_ = std::make_unique<btRigidBody>(
      btRigidBody::btRigidBodyConstructionInfo(0.0, &motion_, &shape_));
  body_->setFriction(0.0);
  world_.addRigidBody(body_.get());
}

StaticSphere::~StaticSphere() { world_.removeRigidBody(body_.get()); }

}  // namespace reference
