#include "deformable_forces.h"

namespace reference {

void DeformableWindForce::addScaledForces(btScalar scale, TVStack& force) {
  addScaledExplicitForce(scale, force);
}

void DeformableWindForce::addScaledExplicitForce(btScalar scale, TVStack& force) {
  for (int b = 0; b < m_softBodies.size(); ++b) {
    const btSoftBody* body = m_softBodies[b];
    for (int p = 0; p < body->m_nodes.size(); ++p) {
      const btSoftBody::Node& node = body->m_nodes[p];
      if (node.m_im == 0) continue;
      const mysim::Vec3 f = mysim::windForce(wind_, p, *time_);
      force[node.index] += scale * btVector3(f.x(), f.y(), f.z());
    }
  }
}

void DeformableDragForce::addScaledDampingForce(btScalar scale, TVStack& force) {
  forFreeNodes([&](const btSoftBody::Node& node, int i) { force[i] -= scale * drag_ * node.m_v; });
}

void DeformableDragForce::addScaledDampingForceDifferential(btScalar scale, const TVStack& dv,
                                                            TVStack& df) {
  forFreeNodes([&](const btSoftBody::Node&, int i) { df[i] -= scale * drag_ * dv[i]; });
}

void DeformableDragForce::buildDampingForceDifferentialDiagonal(btScalar scale, TVStack& diagonal) {
  forFreeNodes(
      [&](const btSoftBody::Node&, int i) { diagonal[i] -= btVector3(1, 1, 1) * (scale * drag_); });
}

}  // namespace reference
