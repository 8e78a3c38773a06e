#pragma once
#include <expected>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mysim/ode_system.h"

namespace mysim {

// What one call to step() did, summed over a run.
struct StepCounts {
  long accepted = 0;  // accepted (sub)steps
  long rejected = 0;  // rejected trial steps (adaptive only)
  long derivative_evaluations = 0;  // -1: unknown (an external engine that did not say)
  // Backward Euler: CG iterations; XPBD: constraint passes; local/global: global solves;
  // vertex block descent: passes over the vertices.
  long linear_iterations = 0;
  long solver_failures = 0;    // linear solves that did not reach their tolerance
  // An adaptive method could not meet its tolerance within its limits (minimum step, maximum
  // internal steps): the step stopped short and the run must stop there.
  bool gave_up = false;
  // Wall time of one-time set-up inside the steps (local/global's factorisation, once per scene
  // and step size), s: reported apart, so a step's cost is not mistaken for it.
  double setup_seconds = 0.0;

  StepCounts& operator+=(const StepCounts& o);
};

// Backward Euler's CG preconditioner (docs/performance.md measures each): symmetric
// successive over-relaxation with the 3x3 blocks (fewest iterations, but its sweeps run on one
// core), the inverses of the 3x3 diagonal blocks, or the plain diagonal. Auto, the default, takes
// the whole factor (Cholesky, below) where hinges bend a system of up to 12500 particles, and
// SSOR where the springs dominate the masses ((h c + h^2 k)/m > 1 for the most damped and the
// stiffest springs on a free particle: large steps, where CG needs tens of iterations) and block
// Jacobi below, where a few parallel iterations cost less than SSOR's serial sweeps (measured
// crossing near h^2 k/m = 1 on 32 x 32 and 64 x 64 cloths, 1 and 2 threads).
// Cholesky: the step's whole matrix factored (a sparse LDL^T), so CG stops after one iteration,
// and the factor kept while it brings later steps' CG to the tolerance in a few: a direct solve,
// for small stiff systems such as a hinge strip, where the others need hundreds of iterations
// (docs/performance.md "A direct solve for backward Euler").
enum class CgPreconditioner { Auto, Jacobi, BlockJacobi, Ssor, Cholesky };
const char* preconditionerName(CgPreconditioner preconditioner);
// By name ("auto", "jacobi", "block-jacobi", "ssor", "cholesky"), or an error listing them.
std::expected<CgPreconditioner, std::string> preconditionerByName(std::string_view name);

struct IntegratorSettings {
  std::string name = "rk4";
  double abs_tolerance = 1e-6;   // adaptive: per-component absolute error bound
  double rel_tolerance = 1e-6;   // adaptive: relative error bound
  double cg_tolerance = 1e-8;    // backward Euler: CG relative residual
  int cg_max_iterations = 1000;  // backward Euler
  CgPreconditioner preconditioner = CgPreconditioner::Auto;  // backward Euler
  // The catalogue's numeric parameters without a field above, by name (every integrator's,
  // defaults filled in by the scene reader: a scene may carry several methods' settings).
  std::map<std::string, double> values;
  // A parameter of `values`, or its catalogue default when none was read.
  double value(const std::string& name) const;
};

// Advances a state by h. Owns its scratch buffers (allocated on first use, reused after), so one
// instance serves one run. A step ends with system.afterStep() applied.
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual StepCounts step(OdeSystem& system, State& state, double h) = 0;
};

// A setting of the scene's "integrator" section that an integrator reads.
struct IntegratorParameter {
  std::string name;      // the scene field, integrator.NAME
  std::string fallback;  // its default, as a scene would write it
  std::string meaning;
  // Read into IntegratorSettings::values by the scene reader, as a number in [low, high]
  // (integer when asked); off for the settings with fields of their own.
  bool in_values = false;
  double low = 0.0, high = 0.0;
  bool integer = false;
};

// How an integrator's method is classed, for tables and the report's styles.
enum class IntegratorFamily {
  Explicit,
  Symplectic,
  Implicit,       // Newton-Krylov implicit Euler
  Adaptive,
  PositionBased,  // constraint projection (XPBD)
  LocalGlobal,    // implicit Euler by alternating projections and one constant factorisation
  BlockDescent,   // implicit Euler by per-vertex Newton steps (vertex block descent)
};
const char* familyName(IntegratorFamily family);
// The families whose step is passes to a tolerance (pass_control.h): XPBD, local/global, VBD.
inline bool iterativeFamily(IntegratorFamily f) {
  return f == IntegratorFamily::PositionBased || f == IntegratorFamily::LocalGlobal ||
         f == IntegratorFamily::BlockDescent;
}

// One row per integrator: everything any study, table, benchmark or test asks of a method, so
// adding one takes its own file (a make... factory) and a row here, nothing else.
struct IntegratorInfo {
  std::string name;
  std::string alias;  // the seed's one-letter name, if any
  std::string description;
  bool needs_particles;  // second-order methods need a ParticleSystem (x' = v, v' = a)
  std::function<std::unique_ptr<Integrator>(const IntegratorSettings&)> make;
  int order = 1;  // global order of accuracy in h
  IntegratorFamily family = IntegratorFamily::Explicit;
  // Theory's largest stable h w on the linear oscillator u'' + 2 zeta w u' + w^2 u = 0 at damping
  // ratio zeta (the edge of the method's stability region along the eigenvalues w(-zeta +- i)):
  // infinity when stable at any step, none when theory gives no closed form.
  std::function<std::optional<double>(double zeta)> stable_h_omega;
  std::vector<IntegratorParameter> parameters;
  // Picks its own internal steps to meet abs/rel tolerance: the tolerance is its accuracy knob.
  bool adaptive() const { return family == IntegratorFamily::Adaptive; }
};
const std::vector<IntegratorInfo>& integratorCatalog();
// The catalogue's names, in its order; without adaptive ones when fixed_step_only (the studies
// that choose the step themselves).
std::vector<std::string> integratorNames(bool fixed_step_only = false);
const IntegratorInfo* findIntegrator(std::string_view name);  // by name or alias

// Why `name` cannot step the circle (a first-order ODE, no particles: only the catalogue's rows
// that do not need a particle system can), naming those that can; nothing if it can (or is not
// in the catalogue: that is canonicalIntegratorName's refusal).
std::optional<std::string> circleRefusal(std::string_view name);

// Canonical name for a name or alias, or an error listing the valid ones.
std::expected<std::string, std::string> canonicalIntegratorName(std::string_view name);

// An integrator with some of its numeric catalogue parameters set, as a sweep names it:
// "NAME" or "NAME:PARAMETER=VALUE[:PARAMETER=VALUE...]" (for example "xpbd:substeps=10:iterations=1").
struct IntegratorVariant {
  std::string name;                      // canonical
  std::map<std::string, double> values;  // parameters the text sets
  std::string text() const;              // canonical text: name, then parameters in name order
};
// Checks the name and each parameter against the catalogue (declared by that integrator, in its
// range, an integer where it must be); an error names what is wrong.
std::expected<IntegratorVariant, std::string> parseIntegratorVariant(std::string_view text);

std::expected<std::unique_ptr<Integrator>, std::string> makeIntegrator(
    const IntegratorSettings& settings);

}  // namespace mysim
