#include "mysim/energy.h"

#include "mysim/model.h"

namespace mysim {

EnergyTerms mechanicalEnergy(const Model& model, Eigen::Ref<const Vector> x,
                             Eigen::Ref<const Vector> v) {
  EnergyTerms e;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    const double m = model.mass[p];
    e.kinetic += 0.5 * m * v.segment<3>(3 * p).squaredNorm();
    e.gravity -= m * model.gravity.dot(x.segment<3>(3 * p));
  }
  for (const Spring& s : model.springs) {
    const double stretch = (x.segment<3>(3 * s.j) - x.segment<3>(3 * s.i)).norm() - s.rest_length;
    e.spring += 0.5 * s.stiffness * stretch * stretch;
  }
  e.spring += hingeEnergy(model.hinges, x);
  return e;
}

}  // namespace mysim
