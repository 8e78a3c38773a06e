#include "mysim/chain.h"

namespace mysim {

void buildChain(const ChainShape& shape, Model& model) {
  const int n = shape.particles;
  model.mass = Vector::Constant(n, shape.particle_mass);
  model.pinned.assign(n, 0);
  model.start_position.resize(3 * n);
  model.start_velocity = Vector::Zero(3 * n);
  const double spacing = shape.spacing > 0.0 ? shape.spacing : shape.rest_length;
  const Vec3 step = spacing * shape.direction.normalized();
  for (int p = 0; p < n; ++p) at3(model.start_position, p) = shape.origin + p * step;
  model.springs.clear();
  for (int p = 0; p + 1 < n; ++p) {
    model.springs.push_back(
        {p, p + 1, shape.rest_length, shape.stiffness, shape.damping, SpringFamily::Chain});
  }
}

}  // namespace mysim
