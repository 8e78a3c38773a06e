#include "mysim/integrator.h"

namespace mysim {

StepCounts& StepCounts::operator+=(const StepCounts& o) {
  accepted += o.accepted;
  rejected += o.rejected;
  derivative_evaluations += o.derivative_evaluations;
  linear_iterations += o.linear_iterations;
  solver_failures += o.solver_failures;
  return *this;
}

const std::vector<IntegratorInfo>& integratorCatalog() {
  static const std::vector<IntegratorInfo> catalog = {
      {"euler", "e", "forward Euler, order 1", false},
      {"trapezoidal", "t", "trapezoidal rule (Heun), order 2", false},
      {"rk4", "r", "classical Runge-Kutta, order 4", false},
      {"symplectic-euler", "", "semi-implicit Euler, order 1, symplectic", true},
      {"verlet", "", "velocity Verlet, order 2, symplectic", true},
      {"backward-euler", "", "Baraff-Witkin implicit Euler (1 Newton step, CG), order 1", true},
      {"dopri5", "", "adaptive Dormand-Prince 5(4), abs/rel tolerance", false},
  };
  return catalog;
}

std::expected<std::string, std::string> canonicalIntegratorName(std::string_view name) {
  std::string valid;
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (name == info.name || (!info.alias.empty() && name == info.alias)) return info.name;
    valid += (valid.empty() ? "" : ", ") + info.name;
    if (!info.alias.empty()) valid += " (" + info.alias + ")";
  }
  return std::unexpected("unknown integrator '" + std::string(name) + "'; expected one of " +
                         valid);
}

std::expected<std::unique_ptr<Integrator>, std::string> makeIntegrator(
    const IntegratorSettings& settings) {
  auto name = canonicalIntegratorName(settings.name);
  if (!name) return std::unexpected(name.error());
  if (*name == "euler") return makeForwardEuler();
  if (*name == "trapezoidal") return makeTrapezoidal();
  if (*name == "rk4") return makeRk4();
  if (*name == "symplectic-euler") return makeSymplecticEuler();
  if (*name == "verlet") return makeVelocityVerlet();
  if (*name == "backward-euler") {
    return makeBackwardEuler(settings.cg_tolerance, settings.cg_max_iterations);
  }
  return makeDormandPrince(settings.abs_tolerance, settings.rel_tolerance);
}

}  // namespace mysim
