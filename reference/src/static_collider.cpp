#include "static_collider.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include <algorithm>
#include <optional>

namespace reference {
namespace {

btVector3 bt(const mysim::Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Each shape's Bullet twin: its convex shape and where it sits.
struct BulletShape {
  std::unique_ptr<btCollisionShape> shape;
  btTransform placement;
};

BulletShape bulletShape(const mysim::Sphere& s) {
  return {std::make_unique<btSphereShape>(s.radius),
          btTransform(btMatrix3x3::getIdentity(), bt(s.center))};
}

BulletShape bulletShape(const mysim::Box& b) {
  return {std::make_unique<btBoxShape>(bt(b.half_extents)),
          btTransform(btMatrix3x3::getIdentity(), bt(b.center))};
}

// Half the side of the box that stands for a plane: far beyond any scene (a cloth of metres)
// yet small enough that GJK's distances keep ~1e-12 m of precision in double.
constexpr double kPlaneBoxHalf = 1e3;

BulletShape bulletShape(const mysim::Plane& p) {
  // The box's +y face lies on the plane: rotate +y onto the normal, centre the box behind it.
  const btQuaternion turn = shortestArcQuat(btVector3(0, 1, 0), bt(p.normal));
  const mysim::Vec3 centre = p.point - kPlaneBoxHalf * p.normal;
  return {std::make_unique<btBoxShape>(btVector3(kPlaneBoxHalf, kPlaneBoxHalf, kPlaneBoxHalf)),
          btTransform(turn, bt(centre))};
}

// The voxel a shape's curvature needs; none for a flat one.
std::optional<double> voxelSize(const mysim::Sphere& s) { return s.radius / 10; }
std::optional<double> voxelSize(const mysim::Box& b) { return b.half_extents.minCoeff() / 5; }
std::optional<double> voxelSize(const mysim::Plane&) { return std::nullopt; }

}  // namespace

StaticCollider::StaticCollider(btDiscreteDynamicsWorld& world, const mysim::Collider& collider)
    : world_(world) {
  BulletShape twin = std::visit([](const auto& shape) { return bulletShape(shape); }, collider);
  shape_ = std::move(twin.shape);
  motion_ = btDefaultMotionState(twin.placement);
  body_ = std::make_unique<btRigidBody>(
      btRigidBody::btRigidBodyConstructionInfo(0.0, &motion_, shape_.get()));
  // Bullet's soft-body contacts use kDF x this friction (both Bullet solvers, docs/reference.md);
  // the steppers set kDF = 1 when a collider has friction, so this is the coefficient itself.
  // Bullet has one coefficient: checkSupported refuses a static one above the kinetic.
  body_->setFriction(mysim::colliderFriction(collider).kinetic);
  world_.addRigidBody(body_.get());
}

StaticCollider::~StaticCollider() { world_.removeRigidBody(body_.get()); }

std::vector<std::unique_ptr<StaticCollider>> addColliders(
    btDiscreteDynamicsWorld& world, const std::vector<mysim::Collider>& colliders) {
  std::vector<std::unique_ptr<StaticCollider>> bodies;
  for (const mysim::Collider& c : colliders) bodies.push_back(std::make_unique<StaticCollider>(world, c));
  return bodies;
}

bool anyFriction(const std::vector<mysim::Collider>& colliders) {
  return std::ranges::any_of(colliders,
                             [](const mysim::Collider& c) { return mysim::colliderFriction(c).any(); });
}

double sdfVoxelSize(const std::vector<mysim::Collider>& colliders) {
  std::optional<double> size;
  for (const mysim::Collider& c : colliders) {
    const auto own = std::visit([](const auto& shape) { return voxelSize(shape); }, c);
    if (own) size = std::min(size.value_or(*own), *own);
  }
  return size.value_or(0.25);
}

double softBodyMargin(const std::vector<mysim::Collider>& colliders) {
  if (colliders.empty()) return 1e-3;
  double margin = 1e-4;
  for (const mysim::Collider& c : colliders) margin = std::max(margin, mysim::colliderMargin(c));
  return margin;
}

}  // namespace reference
