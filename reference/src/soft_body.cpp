#include "soft_body.h"

namespace reference {
btSoftBody* buildSoftBody(
    btSoftBodyWorldInfo& info, const mysim::Model& model,
    const std::function<btSoftBody::Material*(btSoftBody&, const mysim::Spring&)>& material) {
  const int n = model.particleCount();
  btAlignedObjectArray<btVector3> positions;
  btAlignedObjectArray<btScalar> masses;
  positions.resize(n);
  masses.resize(n);
  for (int p = 0; p < n; ++p) {
    positions[p] = toBt(mysim::at3(model.start_position, p));
    masses[p] = model.pinned[p] ? 0.0 : model.mass[p];
  }
  auto* body = new btSoftBody(&info, n, &positions[0], &masses[0]);
  for (int p = 0; p < n; ++p) {
    body->m_nodes[p].index = p;  // the deformable solver addresses nodes by this index
    // m_vn is the implicit solve's v_n: left at zero, the first step would forget the start
    // velocity (measured: a free particle launched at 2.2 m/s landed 2.2 m off after 1 s).
    body->m_nodes[p].m_v = body->m_nodes[p].m_vn = toBt(mysim::at3(model.start_velocity, p));
  }
  for (const mysim::Spring& s : model.springs) {
    body->appendLink(s.i, s.j, material(*body, s));
    body->m_links[body->m_links.size() - 1].m_bbending = s.family == mysim::SpringFamily::Flex;
  }
  body->updateConstants();
  for (int k = 0; k < body->m_links.size(); ++k) {
    btSoftBody::Link& link = body->m_links[k];
    link.m_rl = model.springs[k].rest_length;
    link.m_c1 = link.m_rl * link.m_rl;
  }
  body->m_bUpdateRtCst = false;
  return body;
}

void drivePins(btSoftBody& body, const mysim::Model& model, double t, double h) {
  if (!model.pin_motion) return;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (!model.pinned[p]) continue;
    btSoftBody::Node& node = body.m_nodes[p];
    node.m_v = (toBt(mysim::pinnedPosition(model, p, t + h)) - node.m_x) / h;
  }
}

void placePins(btSoftBody& body, const mysim::Model& model, double t) {
  for (int p = 0; p < model.particleCount(); ++p) {
    if (!model.pinned[p]) continue;
    btSoftBody::Node& node = body.m_nodes[p];
    node.m_x = node.m_q = toBt(mysim::pinnedPosition(model, p, t));
    node.m_v = node.m_vn = toBt(mysim::pinnedVelocity(model, t));
  }
}

void stepWorld(btDiscreteDynamicsWorld& world, btSoftBody& body, const mysim::Model& model,
               mysim::State& state, double h) {
  drivePins(body, model, state.t, h);
  world.stepSimulation(h, 0);
  state.t += h;
  placePins(body, model, state.t);
  readNodes(body, state);
}

void readNodes(const btSoftBody& body, mysim::State& state) {
  const int n = body.m_nodes.size();
  state.y.resize(6 * n);
  for (int p = 0; p < n; ++p) {
    const btSoftBody::Node& node = body.m_nodes[p];
    for (int k = 0; k < 3; ++k) {
      state.y[3 * p + k] = node.m_x[k];
      state.y[3 * n + 3 * p + k] = node.m_v[k];
    }
  }
}

}  // namespace reference
