#pragma once
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>

#include <functional>

#include "mysim/model.h"
#include "mysim/state.h"

namespace reference {

inline btVector3 toBt(const mysim::Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }

// One node per particle in mysim's order (pinned: mass 0, which Bullet reads as immovable), one
// link per spring with `material(spring)`, flex springs flagged as bending links. Rest lengths are
// the model's own: Bullet resets them to the current distances whenever it updates its constants,
// so this calls updateConstants() itself, then writes the model's rest lengths back and clears
// the pending-update flag (the pitfall in docs/reference.md).
btSoftBody* buildSoftBody(
    btSoftBodyWorldInfo& info, const mysim::Model& model,
    const std::function<btSoftBody::Material*(btSoftBody&, const mysim::Spring&)>& material);

// Pinned nodes follow the pin motion: before a step, their velocity is set to land exactly on the
// prescribed position at t + h; after it, position and velocity are set to the prescription.
void drivePins(btSoftBody& body, const mysim::Model& model, double t, double h);
void placePins(btSoftBody& body, const mysim::Model& model, double t);

// Copies node positions and velocities into y = [x; v].
void readNodes(const btSoftBody& body, mysim::State& state);

// One scene step of a Bullet world: pins driven to land on x(t + h), exactly one
// stepSimulation(h, 0), pins placed exactly, node state copied into `state`.
void stepWorld(btDiscreteDynamicsWorld& world, btSoftBody& body, const mysim::Model& model,
               mysim::State& state, double h);

}  // namespace reference
