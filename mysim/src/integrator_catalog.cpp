#include "mysim/integrator.h"

namespace mysim {

StepCounts& StepCounts::operator+=(const StepCounts& o) {
  accepted += o.accepted;
  rejected += o.rejected;
  derivative_evaluations += o.derivative_evaluations;
  linear_iterations += o.linear_iterations;
  solver_failures += o.solver_failures;
  gave_up = gave_up || o.gave_up;
  return *this;
}

const std::vector<IntegratorInfo>& integratorCatalog() {
  using S = const IntegratorSettings&;
  static const std::vector<IntegratorInfo> catalog = {
      {"euler", "e", "forward Euler, order 1", false, [](S) { return makeForwardEuler(); }},
      {"trapezoidal", "t", "trapezoidal rule (Heun), order 2", false,
       [](S) { return makeTrapezoidal(); }},
      {"rk4", "r", "classical Runge-Kutta, order 4", false, [](S) { return makeRk4(); }},
      {"symplectic-euler", "", "semi-implicit Euler, order 1, symplectic", true,
       [](S) { return makeSymplecticEuler(); }},
      {"verlet", "", "velocity Verlet, order 2, symplectic", true,
       [](S) { return makeVelocityVerlet(); }},
      {"backward-euler", "", "Baraff-Witkin implicit Euler (1 Newton step, CG), order 1", true,
       [](S s) {
         return makeBackwardEuler(s.cg_tolerance, s.cg_max_iterations, s.preconditioner);
       }},
      {"dopri5", "", "adaptive Dormand-Prince 5(4), abs/rel tolerance", false,
       [](S s) { return makeDormandPrince(s.abs_tolerance, s.rel_tolerance); }, true},
  };
  return catalog;
}

const char* preconditionerName(CgPreconditioner preconditioner) {
  switch (preconditioner) {
    case CgPreconditioner::Auto:
      return "auto";
    case CgPreconditioner::Jacobi:
      return "jacobi";
    case CgPreconditioner::BlockJacobi:
      return "block-jacobi";
    case CgPreconditioner::Ssor:
      return "ssor";
  }
  return "?";
}

std::expected<CgPreconditioner, std::string> preconditionerByName(std::string_view name) {
  for (CgPreconditioner p : {CgPreconditioner::Auto, CgPreconditioner::Jacobi,
                             CgPreconditioner::BlockJacobi, CgPreconditioner::Ssor}) {
    if (name == preconditionerName(p)) return p;
  }
  return std::unexpected("unknown CG preconditioner '" + clip(std::string(name), 40) +
                         "'; expected one of auto, jacobi, block-jacobi, ssor");
}

const IntegratorInfo* findIntegrator(std::string_view name) {
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (name == info.name || (!info.alias.empty() && name == info.alias)) return &info;
  }
  return nullptr;
}

std::expected<std::string, std::string> canonicalIntegratorName(std::string_view name) {
  if (const IntegratorInfo* info = findIntegrator(name)) return info->name;
  std::string valid;
  for (const IntegratorInfo& info : integratorCatalog()) {
    valid += (valid.empty() ? "" : ", ") + info.name;
    if (!info.alias.empty()) valid += " (" + info.alias + ")";
  }
  return std::unexpected("unknown integrator '" + clip(std::string(name), 40) +
                         "'; expected one of " + valid);
}

std::expected<std::unique_ptr<Integrator>, std::string> makeIntegrator(
    const IntegratorSettings& settings) {
  const IntegratorInfo* info = findIntegrator(settings.name);
  if (!info) return std::unexpected(canonicalIntegratorName(settings.name).error());
  return info->make(settings);
}

}  // namespace mysim
