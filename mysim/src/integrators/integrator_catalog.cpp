#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <limits>

#include "mysim/integrator.h"
#include "integrators/halving_steps.h"

namespace mysim {

StepCounts& StepCounts::operator+=(const StepCounts& o) {
  accepted += o.accepted;
  rejected += o.rejected;
  derivative_evaluations += o.derivative_evaluations;
  linear_iterations += o.linear_iterations;
  solver_failures += o.solver_failures;
  gave_up = gave_up || o.gave_up;
  setup_seconds += o.setup_seconds;
  return *this;
}

// Each method's factory, defined in its own file (adding a method: that file and a row below).
std::unique_ptr<Integrator> makeForwardEuler();
std::unique_ptr<Integrator> makeTrapezoidal();
std::unique_ptr<Integrator> makeRk4();
std::unique_ptr<Integrator> makeSymplecticEuler();
std::unique_ptr<Integrator> makeVelocityVerlet();
std::unique_ptr<Integrator> makeBackwardEuler(
    double cg_tolerance, int cg_max_iterations,
    CgPreconditioner preconditioner = CgPreconditioner::Auto);
std::unique_ptr<Integrator> makeDormandPrince(double abs_tolerance, double rel_tolerance);
std::unique_ptr<Integrator> makeXpbd(const IntegratorSettings& settings);
std::unique_ptr<Integrator> makeLocalGlobal(const IntegratorSettings& settings);
std::unique_ptr<Integrator> makeVertexBlockDescent(const IntegratorSettings& settings);

namespace {

using Limit = std::optional<double>;
constexpr double kUnconditional = std::numeric_limits<double>::infinity();

// Stability edges on the oscillator's eigenvalues h lambda = h w (-zeta +- i):
//   forward Euler |1 + h lambda| < 1  <=>  h w < 2 zeta (exactly);
//   symplectic Euler and velocity Verlet (undamped): h w < 2;
//   RK4 on the imaginary axis: h w < 2 sqrt(2);
//   backward Euler |1 / (1 - h lambda)| < 1 for every h > 0.
// Heun's |1 + z + z^2/2| exceeds 1 on the whole imaginary axis (undamped: unstable at any h, 0),
// with no short closed form under damping: none.
// Backward Euler's limit at large steps is not its stability but its one Newton step, linearised
// at the step's start: parts turning through tens of degrees a step are not followed (the
// 32-ring Cusick drape's hinges by the clamp and the quarter and three-eighths capstans' links,
// at 1/60 s: energy-rise within a few steps; both run at 1/240 s; docs/performance.md "Every
// family on every shipped material and cloth scene"). The iterative families solve those steps.
const std::vector<IntegratorParameter> kBackwardEulerParameters = {
    {"cg_tolerance", "1e-8", "CG relative residual of the linear solve"},
    {"cg_max_iterations", "1000", "CG iteration limit per step"},
    {"cg_preconditioner", "auto", "auto, jacobi, block-jacobi, ssor or cholesky (a direct solve)"}};
// The iterative families' stopping rule (pass_control.h): after `iterations` passes, on until
// the forces left unbalanced are `tolerance` of the forces acting, at most 1000 passes. Measured
// at 1/60 s (docs/performance.md "Passes to a tolerance"): with a fixed ten passes XPBD and VBD
// blow up on a 32 x 32 hanging cloth (h w = 7.5) and all three families on a hinge cantilever.
// XPBD and local/global at 1 % run both through and settle within 0.7 mm of backward Euler on
// the cloth (local/global's 1000-pass cap holds it 3 mm off on the strip: its constant matrix
// turns a stiff membrane slowly); 0.1 % costs them 2 to 4 times the passes for no closer shape.
// VBD at 1 % leaves the cloth moving at 12 s (kinetic energy 1.4e-6 J plain, 6.7e-7 J with
// Chebyshev, against backward Euler's 2e-12 J; 0.8 to 0.9 mm off): its default is 0.1 %, with
// Chebyshev acceleration (below): 0.68 mm, 3e-8 J, in 44 passes a step (126 without).
IntegratorParameter passTolerance(const char* fallback) {
  return {"tolerance", fallback,
          "after `iterations` passes, go on until the forces left unbalanced are this fraction of "
          "the forces acting; 0: exactly `iterations` passes",
          true, 0.0, 0.5, false};
}
// Chebyshev acceleration (integrators/chebyshev.h) of local/global's and VBD's passes; each family
// says why its default is that number.
IntegratorParameter accelerationRho(const char* fallback) {
  return {"acceleration_rho", fallback,
          "Chebyshev acceleration's spectral radius estimate, in [0, 1); 0 turns it off", true, 0.0,
          0.999, false};
}
const IntegratorParameter kMaxPasses = {
    "max_iterations", "1000", "most passes per step (per substep) when tolerance > 0; a step that "
    "stops there is redone as two halves (max_halvings), or counts a solver failure", true, 1,
    1000000, true};
// 6 (a 1/60 s step down to 1/3840 s): the shipped cantilever at 32 cells and 1/60 s (h^2 k / m ~
// 1e5, the stiffest step of a shipped scene) is solved by every family with no piece left
// unsolved, in 2 to 4.3 pieces a step on average (docs/performance.md "Halving unsolved steps");
// the levels beyond are room for stiffer scenes, and a scene no level solves stops halving after
// its first failure at the deepest. Scenes whose steps solve at h never halve (the plain bits).
const IntegratorParameter kMaxHalvings = {
    "max_halvings", "6", "times a step the passes cannot solve within max_iterations is halved "
    "(halves solved the same way, the level kept for the next steps); 0: never", true, 0, 20, true};
// XPBD's defaults: the small-steps form (Macklin 2019): ten substeps of at least one pass. With
// one substep its passes pull each spring back from its predicted stretch with lambda starting
// at 0 every step, and on a hanging cloth the tension near the pins settles 4.5 mm off backward
// Euler's shape however many passes; ten substeps settle it within 0.7 mm in a sixth of the time
// (32 x 32, 1/60 s).
const std::vector<IntegratorParameter> kXpbdParameters = {
    // 40 substeps, warm started: measured on the check cloth (docs/performance.md "XPBD at
    // rest"): XPBD's substep drops the term M (x - x~) - grad C^T lambda of its system, so a cloth
    // at rest settles away from the force balance by an amount that falls with h_s (32 x 32, 24 s
    // at 1/60 s: 0.70 mm from backward Euler's settled shape at 10 substeps, 0.68 at 20, 0.03 at
    // 40; 128 x 128: 1.27 mm at 10, 0.60 at 40), and warm started (warm_start below) a substep
    // needs one pass where it needed three to seven from lambda = 0: 40 warm substeps take 0.57
    // of the old 10 cold ones' passes at 32 cells and 0.06 at 128.
    {"substeps", "40",
     "substeps per step (Macklin 2019: the same work spent on substeps beats "
     "iterations)",
     true, 1, 10000, true},
    {"iterations", "1", "Gauss-Seidel passes over the springs per substep (at least)", true, 1,
     10000, true},
    passTolerance("1e-2"), kMaxPasses, kMaxHalvings,
    {"warm_start", "1",
     "1: with a tolerance, each substep's multipliers start from the last substep's (scaled to "
     "its h_s^2) instead of 0, so a substep near rest needs one pass (the fixed-count form, "
     "tolerance 0, always starts from 0)",
     true, 0, 1, true}};
// At least ten passes for the two implicit-Euler solvers (the fixed-count form's old default, kept
// as the floor: a step the tolerance lets stop sooner still makes them), then the tolerance.
const std::vector<IntegratorParameter> kLocalGlobalParameters = {
    {"iterations", "10", "local/global passes per step (each: one solve with the factor)", true, 1,
     10000, true},
    passTolerance("1e-2"), kMaxPasses, kMaxHalvings,
    // 0.99 measured (docs/performance.md "Chebyshev for local/global"): every shipped scene at its
    // own step and at 1/60 s, rho 0 / 0.99 / 0.995: no run changes status for the worse, and
    // cloth_stiff at 1/60 s, the cantilever and the Cusick drape at their steps and the flex strip
    // at 1/60 s reach 1 % where plain passes stop at the 1000-pass cap (cusick_drape 409 -> 62
    // passes a step); 0.99 takes fewer passes than 0.995 but on the stiffest (cloth_stiff and the
    // strips at 1/60 s).
    accelerationRho("0.99")};
const std::vector<IntegratorParameter> kVbdParameters = {
    {"iterations", "10", "passes over the vertices per step", true, 1, 10000, true},
    passTolerance("1e-3"), kMaxPasses, kMaxHalvings,
    // 0.95 measured (docs/performance.md): on the 32 x 32 cloth at 1/60 s it cuts the passes to
    // 0.1 % 3.3 times (126 to 38 a step), on the cantilever 2 to 3 times with fewer steps at the
    // cap, the same settled shape within 1e-6 m; 0.98 overshoots (more passes than none).
    accelerationRho("0.95")};
std::unique_ptr<Integrator> halving(std::unique_ptr<Integrator> solver, const IntegratorSettings& s) {
  return halvingUnsolvedSteps(std::move(solver), static_cast<int>(s.value("max_halvings")));
}
const std::vector<IntegratorParameter> kAdaptiveParameters = {
    {"abs_tolerance", "1e-6", "per-component absolute error bound per step"},
    {"rel_tolerance", "1e-6", "relative error bound per step"}};

}  // namespace

// The iterative families (XPBD, local/global, VBD) solve the implicit-Euler step (XPBD: each
// substep), unconditionally stable once solved; solved to a tolerance, their limit is the step
// whose passes no longer reach it within the cap (Gauss-Seidel needs passes growing as (h w)^2),
// which the stability maps measure, counting a capped step as failed (docs/performance.md
// "Passes to a tolerance"). A capped step is halved until it solves (max_halvings,
// integrators/halving_steps.h): on a stiff membrane bending far (the shipped cantilever at 32
// cells, 1/60 s, h^2 k / m ~ 1e5) VBD's passes blew up unsolved and local/global stopped 8 % off;
// halved, every family solves it within 0.1 % of the heavy elastica. With max_halvings 0 the
// plain limits stand. What halving cannot repair, from theory: implicit Euler loses energy only
// where the energy it descends is convex, and a spring folded through zero length is not (a link
// of the chain pile landing at 1/60 s moves twice its rest length a step): there backward Euler
// and VBD blow up at 1/60 s with every step solved, and run whole at 1/240 s (docs/contact.md).
const std::vector<IntegratorInfo>& integratorCatalog() {
  using S = const IntegratorSettings&;
  using F = IntegratorFamily;
  static const std::vector<IntegratorInfo> catalog = {
      {"euler", "e", "forward Euler", false, [](S) { return makeForwardEuler(); }, 1, F::Explicit,
       [](double zeta) { return Limit(2 * zeta); }, {}},
      {"trapezoidal", "t", "trapezoidal rule (Heun)", false, [](S) { return makeTrapezoidal(); }, 2,
       F::Explicit, [](double zeta) { return zeta == 0.0 ? Limit(0.0) : Limit(); }, {}},
      {"rk4", "r", "classical Runge-Kutta", false, [](S) { return makeRk4(); }, 4, F::Explicit,
       [](double) { return Limit(2 * std::sqrt(2.0)); }, {}},
      {"symplectic-euler", "", "semi-implicit Euler", true, [](S) { return makeSymplecticEuler(); },
       1, F::Symplectic, [](double) { return Limit(2.0); }, {}},
      {"verlet", "", "velocity Verlet", true, [](S) { return makeVelocityVerlet(); }, 2,
       F::Symplectic, [](double) { return Limit(2.0); }, {}},
      {"backward-euler", "", "Baraff-Witkin implicit Euler (1 Newton step, CG)", true,
       [](S s) { return makeBackwardEuler(s.cg_tolerance, s.cg_max_iterations, s.preconditioner); },
       1, F::Implicit, [](double) { return Limit(kUnconditional); }, kBackwardEulerParameters},
      {"dopri5", "", "Dormand-Prince 5(4), abs/rel tolerance", false,
       [](S s) { return makeDormandPrince(s.abs_tolerance, s.rel_tolerance); }, 5, F::Adaptive,
       [](double) { return Limit(); }, kAdaptiveParameters},
      // Iterative: no theory line (above the catalogue).
      {"xpbd", "", "extended position-based dynamics: springs as compliant distance constraints",
       true, [](S s) { return halving(makeXpbd(s), s); }, 1, F::PositionBased, [](double) { return Limit(); },
       kXpbdParameters},
      // Iterative: no theory line (above the catalogue).
      {"local-global", "",
       "Liu et al. 2013 fast mass-spring: implicit Euler by local/global passes, one factorisation",
       true, [](S s) { return halving(makeLocalGlobal(s), s); }, 1, F::LocalGlobal,
       [](double) { return Limit(); }, kLocalGlobalParameters},
      {"vbd", "", "vertex block descent (Chen et al. 2024): implicit Euler by per-vertex Newton",
       true, [](S s) { return halving(makeVertexBlockDescent(s), s); }, 1, F::BlockDescent,
       [](double) { return Limit(); }, kVbdParameters},
  };
  return catalog;
}

double IntegratorSettings::value(const std::string& key) const {
  if (auto it = values.find(key); it != values.end()) return it->second;
  // The running integrator's own default first: a parameter name is shared by families with
  // different defaults (iterations, tolerance).
  const IntegratorInfo* own = findIntegrator(name);
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (own != nullptr && &info != own) continue;
    for (const IntegratorParameter& p : info.parameters) {
      if (p.name == key) return std::stod(p.fallback);
    }
  }
  return 0.0;
}

std::vector<std::string> integratorNames(bool fixed_step_only) {
  std::vector<std::string> names;
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (!(fixed_step_only && info.adaptive())) names.push_back(info.name);
  }
  return names;
}

std::optional<std::string> circleRefusal(std::string_view name) {
  const IntegratorInfo* info = findIntegrator(name);
  if (info == nullptr || !info->needs_particles) return std::nullopt;
  std::vector<std::string> able;
  for (const IntegratorInfo& row : integratorCatalog()) {
    if (!row.needs_particles) able.push_back(row.name);
  }
  std::string list;
  for (std::size_t k = 0; k < able.size(); ++k) {
    list += (k == 0 ? "" : k + 1 == able.size() ? " or " : ", ") + able[k];
  }
  return "'" + info->name + "' needs a particle system; the circle is a first-order ODE (use " +
         list + ")";
}

const char* familyName(IntegratorFamily family) {
  switch (family) {
    case IntegratorFamily::Explicit:
      return "explicit";
    case IntegratorFamily::Symplectic:
      return "symplectic";
    case IntegratorFamily::Implicit:
      return "implicit";
    case IntegratorFamily::Adaptive:
      return "adaptive";
    case IntegratorFamily::PositionBased:
      return "position-based";
    case IntegratorFamily::LocalGlobal:
      return "local-global";
    case IntegratorFamily::BlockDescent:
      return "block-descent";
  }
  return "?";
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
    case CgPreconditioner::Cholesky:
      return "cholesky";
  }
  return "?";
}

std::expected<CgPreconditioner, std::string> preconditionerByName(std::string_view name) {
  for (CgPreconditioner p : {CgPreconditioner::Auto, CgPreconditioner::Jacobi,
                             CgPreconditioner::BlockJacobi, CgPreconditioner::Ssor,
                             CgPreconditioner::Cholesky}) {
    if (name == preconditionerName(p)) return p;
  }
  return std::unexpected("unknown CG preconditioner '" + clip(std::string(name), 40) +
                         "'; expected one of auto, jacobi, block-jacobi, ssor, cholesky");
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

std::string IntegratorVariant::text() const {
  std::ostringstream out;
  out << name;
  for (const auto& [key, value] : values) out << ':' << key << '=' << value;
  return out.str();
}

std::expected<IntegratorVariant, std::string> parseIntegratorVariant(std::string_view text) {
  const std::size_t colon = text.find(':');
  auto name = canonicalIntegratorName(text.substr(0, colon));
  if (!name) return std::unexpected(name.error());
  IntegratorVariant variant{*name, {}};
  const IntegratorInfo& info = *findIntegrator(*name);
  std::string_view rest = colon == std::string_view::npos ? "" : text.substr(colon + 1);
  while (colon != std::string_view::npos) {
    const std::size_t next = rest.find(':');
    const std::string_view item = rest.substr(0, next);
    const std::size_t equals = item.find('=');
    const std::string key(item.substr(0, equals));
    auto p = std::find_if(info.parameters.begin(), info.parameters.end(),
                          [&](const IntegratorParameter& q) { return q.in_values && q.name == key; });
    if (p == info.parameters.end()) {
      std::string declared;
      for (const IntegratorParameter& q : info.parameters) {
        if (q.in_values) declared += (declared.empty() ? "" : ", ") + q.name;
      }
      return std::unexpected("'" + clip(std::string(text), 60) + "': " + info.name +
                             " has no parameter '" + clip(key, 30) + "'; it has " +
                             (declared.empty() ? "none to set" : declared));
    }
    double value = 0.0;
    const std::string number = equals == std::string_view::npos ? "" : std::string(item.substr(equals + 1));
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || error != std::errc() || end != number.data() + number.size() ||
        value < p->low || value > p->high || (p->integer && value != std::floor(value))) {
      std::ostringstream expected;
      expected << (p->integer ? "an integer" : "a number") << " in [" << p->low << ", " << p->high
               << "]";
      return std::unexpected("'" + clip(std::string(text), 60) + "': " + key + " must be " +
                             expected.str());
    }
    variant.values[key] = value;
    if (next == std::string_view::npos) break;
    rest = rest.substr(next + 1);
  }
  return variant;
}

std::expected<std::unique_ptr<Integrator>, std::string> makeIntegrator(
    const IntegratorSettings& settings) {
  const IntegratorInfo* info = findIntegrator(settings.name);
  if (!info) return std::unexpected(canonicalIntegratorName(settings.name).error());
  return info->make(settings);
}

}  // namespace mysim
