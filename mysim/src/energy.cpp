#include "mysim/energy.h"

#include "mysim/model.h"

namespace mysim {

EnergyTerms mechanicalEnergy(const Model& model, const Vector& x, const Vector& v) {
  EnergyTerms e;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    const double m = model.mass[p];
    e.kinetic += 0.5 * m * at3(v, p).squaredNorm();
    e.gravity -= m * model.gravity.dot(at3(x, p));
  }
  for (const Spring& s : model.springs) {
    const double stretch = (at3(x, s.j) - at3(x, s.i)).norm() - s.rest_length;
    e.spring += 0.5 * s.stiffness * stretch * stretch;
  }
  return e;
}

}  // namespace mysim
