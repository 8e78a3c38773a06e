#pragma once
#include "mysim/energy_terms.h"
#include "mysim/types.h"

namespace mysim {

struct Model;

// Pinned particles are not dynamic (Bullet gives them infinite mass), so they carry no kinetic or
// gravitational energy here; every engine's energy is computed by this one function.
EnergyTerms mechanicalEnergy(const Model& model, Eigen::Ref<const Vector> x,
                             Eigen::Ref<const Vector> v);

}  // namespace mysim
