// Your own integrator, judged like springcheck's: explicit midpoint (RK2) registered as an engine,
// run on the matched hanging chain beside Bullet, and held to the chain's closed-form rest shape.
// Usage: midpoint_check [SCENE]   (default: the installed scenes/matched/chain_hanging.json)
#include <cstdio>
#include <memory>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/closed_form.h"
#include "mysim/integrator.h"
#include "mysim/scene.h"

namespace {

// y(t + h) = y + h f(t + h/2, y + h/2 f(t, y)): second order, two derivative evaluations a step.
class Midpoint final : public mysim::Integrator {
 public:
  mysim::StepCounts step(mysim::OdeSystem& system, mysim::State& s, double h) override {
    system.derivative(s.t, s.y, slope_);
    half_ = s.y + 0.5 * h * slope_;
    system.derivative(s.t + 0.5 * h, half_, slope_);
    s.y += h * slope_;
    s.t += h;
    system.afterStep(s);
    return {.accepted = 1, .derivative_evaluations = 2};
  }

 private:
  mysim::Vector slope_, half_;
};

springcheck::Engine midpointEngine() {
  springcheck::Engine e;
  e.name = "midpoint";
  e.kind = "mysim";
  e.description = "mysim's model stepped by this project's explicit midpoint rule";
  e.build = [](const mysim::Model& model, const springcheck::RunConfig& config)
      -> std::expected<springcheck::EngineInstance, springcheck::EngineError> {
    springcheck::EngineInstance instance;
    instance.system = mysim::makeSystem(model, config.limits);
    instance.stepper =
        std::make_unique<mysim::IntegratorStepper>(*instance.system, std::make_unique<Midpoint>());
    instance.start = instance.system->initialState();
    instance.integrator = "midpoint";
    return instance;
  };
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path =
      argc > 1 ? argv[1] : std::string(SPRINGCHECK_SCENES) + "/matched/chain_hanging.json";
  springcheck::EngineRegistry registry;
  if (auto added = registry.add(midpointEngine()); !added) {
    std::fprintf(stderr, "error: %s\n", added.error().c_str());
    return 2;
  }
  auto scene = registry.loadScene(path);
  if (!scene) {
    std::fprintf(stderr, "error: %s\n", scene.error().c_str());
    return 2;
  }
  const mysim::Model model = mysim::buildModel(*scene);
  int code = 0;
  for (const char* engine : {"midpoint", "bullet-deformable"}) {
    auto run = registry.run(engine, *scene);
    if (!run) {
      std::fprintf(stderr, "error: %s: %s\n", engine, run.error().message.c_str());
      return 2;
    }
    const auto error = springcheck::closedFormError(model, *run);
    std::printf("%-18s status %-6s steps %ld  derivative evaluations %ld", engine,
                run->status().c_str(), run->steps, run->counts.derivative_evaluations);
    if (error) std::printf("  %s error %.3g", error->quantity.c_str(), error->error);
    std::printf("\n");
    // The bound springcheck's own gate holds RK4 and Bullet to on this scene (tolerances.json).
    if (run->status() != "ok" || !error || error->error > 1e-4) code = 1;
  }
  return code;
}
