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

namespace {

// Unit vector along d, or zero for a link of (near) zero length, where Bullet's force uses zero.
btVector3 unitOrZero(const btVector3& d) {
  return d.norm() > SIMD_EPSILON ? d.normalized() : btVector3(0, 0, 0);
}

}  // namespace

void DeformableLinkSpringForce::addScaledElasticForce(btScalar scale, TVStack& force) const {
  forLinks([&](const btSoftBody::Link& link, const LinkParameters& p) {
    const btSoftBody::Node& a = *link.m_n[0];
    const btSoftBody::Node& b = *link.m_n[1];
    const btVector3 d = b.m_q - a.m_q;
    const btVector3 f = scale * p.stiffness * (d - unitOrZero(d) * link.m_rl);
    force[a.index] += f;
    force[b.index] -= f;
  });
}

void DeformableLinkSpringForce::addScaledDampingForce(btScalar scale, TVStack& force) {
  forLinks([&](const btSoftBody::Link& link, const LinkParameters& p) {
    const btSoftBody::Node& a = *link.m_n[0];
    const btSoftBody::Node& b = *link.m_n[1];
    const btVector3 w = b.m_v - a.m_v;
    const btVector3 d = b.m_x - a.m_x;
    // Along the link; a zero-length link has no direction, and Bullet then damps all of w.
    const btVector3 f = d.norm() > SIMD_EPSILON
                            ? scale * p.damping * w.dot(d.normalized()) * d.normalized()
                            : scale * p.damping * w;
    force[a.index] += f;
    force[b.index] -= f;
  });
}

void DeformableLinkSpringForce::addScaledDampingForceDifferential(btScalar scale, const TVStack& dv,
                                                                  TVStack& df) {
  forLinks([&](const btSoftBody::Link& link, const LinkParameters& p) {
    const int ia = link.m_n[0]->index, ib = link.m_n[1]->index;
    const btVector3 w = dv[ib] - dv[ia];
    const btVector3 d = link.m_n[1]->m_x - link.m_n[0]->m_x;
    const btVector3 f = d.norm() > SIMD_EPSILON
                            ? p.damping * scale * w.dot(d.normalized()) * d.normalized()
                            : p.damping * scale * w;
    df[ia] += f;
    df[ib] -= f;
  });
}

void DeformableLinkSpringForce::buildDampingForceDifferentialDiagonal(btScalar scale,
                                                                      TVStack& diagonal) {
  forLinks([&](const btSoftBody::Link& link, const LinkParameters& p) {
    const btSoftBody::Node& a = *link.m_n[0];
    const btSoftBody::Node& b = *link.m_n[1];
    const btVector3 d = b.m_x - a.m_x;
    if (d.norm() <= SIMD_EPSILON) return;
    const btVector3 u = d.normalized();
    for (int k = 0; k < 3; ++k) {
      const double entry = p.damping * scale * u[k] * u[k];
      if (a.m_im > 0) diagonal[a.index][k] -= entry;
      if (b.m_im > 0) diagonal[b.index][k] -= entry;
    }
  });
}

void DeformableLinkSpringForce::addScaledElasticForceDifferential(btScalar scale, const TVStack& dx,
                                                                  TVStack& df) {
  forLinks([&](const btSoftBody::Link& link, const LinkParameters& p) {
    const int ia = link.m_n[0]->index, ib = link.m_n[1]->index;
    const btVector3 d = link.m_n[0]->m_q - link.m_n[1]->m_q;  // from b to a, as Bullet's
    const double length = d.norm();
    if (length <= SIMD_EPSILON) return;
    const btVector3 u = d.normalized();
    const btVector3 delta = dx[ia] - dx[ib];
    const double k = scale * p.stiffness;
    const double stretch = (length - link.m_rl) / length;
    btVector3 f = btVector3(0, 0, 0);
    f -= k * u.dot(delta) * u;
    f += k * u.dot(delta) * stretch * u;
    f -= k * stretch * delta;
    df[ia] += f;
    df[ib] -= f;
  });
}

void DeformableHingeForce::addScaledElasticForce(btScalar scale, TVStack& force) const {
  const btSoftBody& body = *m_softBodies[0];
  for (const mysim::Hinge& h : hinges_) {
    btVector3 b(0, 0, 0);
    for (int a = 0; a < 4; ++a) b += h.weight[a] * body.m_nodes[h.particle[a]].m_q;
    for (int a = 0; a < 4; ++a) {
      force[body.m_nodes[h.particle[a]].index] -= (scale * h.stiffness * h.weight[a]) * b;
    }
  }
}

void DeformableHingeForce::addScaledElasticForceDifferential(btScalar scale, const TVStack& dx,
                                                             TVStack& df) {
  const btSoftBody& body = *m_softBodies[0];
  for (const mysim::Hinge& h : hinges_) {
    btVector3 b(0, 0, 0);
    for (int a = 0; a < 4; ++a) b += h.weight[a] * dx[body.m_nodes[h.particle[a]].index];
    for (int a = 0; a < 4; ++a) {
      df[body.m_nodes[h.particle[a]].index] -= (scale * h.stiffness * h.weight[a]) * b;
    }
  }
}

}  // namespace reference
