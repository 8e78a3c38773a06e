#pragma once
#include <BulletSoftBody/btDeformableLagrangianForce.h>

#include <vector>

#include "mysim/hinge.h"
#include "mysim/wind.h"

namespace reference {

// Forces the deformable world lacks, written against its Lagrangian force interface. Their types
// must differ from Bullet's own (1..6), since addForce merges forces of one type: 7, 8 and 9.

// mysim's gusting wind as a Bullet deformable force: the deformable world ignores
// btSoftBody::setWindVelocity, so the same per-particle force enters through a Lagrangian force.
// It depends on time only, so every differential is zero.
class DeformableWindForce final : public btDeformableLagrangianForce {
 public:
  DeformableWindForce(const mysim::Wind& wind, const double* time) : wind_(wind), time_(time) {}

  void addScaledForces(btScalar scale, TVStack& force) override;
  void addScaledExplicitForce(btScalar scale, TVStack& force) override;
  void addScaledDampingForce(btScalar, TVStack&) override {}
  void addScaledDampingForceDifferential(btScalar, const TVStack&, TVStack&) override {}
  void buildDampingForceDifferentialDiagonal(btScalar, TVStack&) override {}
  void addScaledElasticForceDifferential(btScalar, const TVStack&, TVStack&) override {}
  double totalEnergy(btScalar) override { return 0.0; }
  btDeformableLagrangianForceType getForceType() override {
    return static_cast<btDeformableLagrangianForceType>(7);
  }

 private:
  mysim::Wind wind_;
  const double* time_;  // start of the step being taken, owned by the stepper
};

// Viscous drag F = -c v on every free node, solved with the damping forces (implicitly in both
// modes). Bullet's own m_cfg.drag is a velocity scale applied before the solve, which the
// implicit mode discards (it restarts from v_n): the chain never settled with it.
class DeformableDragForce final : public btDeformableLagrangianForce {
 public:
  explicit DeformableDragForce(double drag) : drag_(drag) {}

  void addScaledForces(btScalar scale, TVStack& force) override {
    addScaledDampingForce(scale, force);
  }
  void addScaledExplicitForce(btScalar, TVStack&) override {}
  void addScaledDampingForce(btScalar scale, TVStack& force) override;
  // dF/dv = -c I.
  void addScaledDampingForceDifferential(btScalar scale, const TVStack& dv, TVStack& df) override;
  void buildDampingForceDifferentialDiagonal(btScalar scale, TVStack& diagonal) override;
  void addScaledElasticForceDifferential(btScalar, const TVStack&, TVStack&) override {}
  double totalEnergy(btScalar) override { return 0.0; }
  btDeformableLagrangianForceType getForceType() override {
    return static_cast<btDeformableLagrangianForceType>(8);
  }

 private:
  // Calls f(node, its index) for every free node.
  template <typename F>
  void forFreeNodes(F f) const {
    for (int b = 0; b < m_softBodies.size(); ++b) {
      for (int p = 0; p < m_softBodies[b]->m_nodes.size(); ++p) {
        const btSoftBody::Node& node = m_softBodies[b]->m_nodes[p];
        if (node.m_im > 0) f(node, node.index);
      }
    }
  }
  double drag_;  // N s/m
};

// Damped Hooke springs with a stiffness and a damping per link (link k = model spring k), for
// models btDeformableMassSpringForce cannot hold (it has one stiffness for non-bending links, one
// for bending links, one damping). The force law is mysim's and Bullet's alike:
//   F_1 = k (|d| - rest) d/|d| + c ((v2 - v1).u) u,   d = x2 - x1, u = d/|d|,   F_2 = -F_1
// with the same split as Bullet's own force: the elastic part from the predicted positions m_q,
// the damping part along the current link direction from m_x, so with uniform parameters it
// gives Bullet's trajectories to round-off (tested). Differentials, for the implicit solve:
//   elastic  dF_1 = -k [ u u^T + (1 - rest/|d|)(I - u u^T) ] (dx_1 - dx_2)
//   damping  dF_1 = c u u^T (dv_2 - dv_1)
class DeformableLinkSpringForce final : public btDeformableLagrangianForce {
 public:
  struct LinkParameters {
    double stiffness, damping;  // N/m, N s/m
  };
  explicit DeformableLinkSpringForce(std::vector<LinkParameters> links)
      : links_(std::move(links)) {}

  void addScaledForces(btScalar scale, TVStack& force) override {
    addScaledDampingForce(scale, force);
    addScaledElasticForce(scale, force);
  }
  void addScaledExplicitForce(btScalar scale, TVStack& force) override {
    addScaledElasticForce(scale, force);
  }
  void addScaledDampingForce(btScalar scale, TVStack& force) override;
  void addScaledDampingForceDifferential(btScalar scale, const TVStack& dv, TVStack& df) override;
  void buildDampingForceDifferentialDiagonal(btScalar scale, TVStack& diagonal) override;
  void addScaledElasticForceDifferential(btScalar scale, const TVStack& dx, TVStack& df) override;
  double totalEnergy(btScalar) override { return 0.0; }  // springcheck computes energy itself
  btDeformableLagrangianForceType getForceType() override {
    return static_cast<btDeformableLagrangianForceType>(9);
  }

 private:
  void addScaledElasticForce(btScalar scale, TVStack& force) const;
  // Calls f(link, its parameters) for every link of every body.
  template <typename F>
  void forLinks(F f) const {
    for (int b = 0; b < m_softBodies.size(); ++b) {
      const btSoftBody* body = m_softBodies[b];
      for (int k = 0; k < body->m_links.size(); ++k) f(body->m_links[k], links_[k]);
    }
  }
  std::vector<LinkParameters> links_;
};

// mysim's hinge bending (mysim/hinge.h) on Bullet's force interface: per hinge b = sum w_a x_a,
// F_a = -k w_a b from the predicted positions m_q (as Bullet's own elastic forces), and the
// constant differential dF_a = -k w_a sum_c w_c dx_c for the implicit solve. Model particle p is
// node p of the one body. No damping.
class DeformableHingeForce final : public btDeformableLagrangianForce {
 public:
  explicit DeformableHingeForce(std::vector<mysim::Hinge> hinges) : hinges_(std::move(hinges)) {}

  void addScaledForces(btScalar scale, TVStack& force) override {
    addScaledElasticForce(scale, force);
  }
  void addScaledExplicitForce(btScalar scale, TVStack& force) override {
    addScaledElasticForce(scale, force);
  }
  void addScaledDampingForce(btScalar, TVStack&) override {}
  void addScaledDampingForceDifferential(btScalar, const TVStack&, TVStack&) override {}
  void buildDampingForceDifferentialDiagonal(btScalar, TVStack&) override {}
  void addScaledElasticForceDifferential(btScalar scale, const TVStack& dx, TVStack& df) override;
  double totalEnergy(btScalar) override { return 0.0; }  // springcheck computes energy itself
  btDeformableLagrangianForceType getForceType() override {
    return static_cast<btDeformableLagrangianForceType>(10);
  }

 private:
  void addScaledElasticForce(btScalar scale, TVStack& force) const;
  std::vector<mysim::Hinge> hinges_;
};

}  // namespace reference
