// External engines: the example Python engine against closed forms and mysim, the model file,
// and every way an engine can misbehave, each refused with a message naming engine and file.
// ctest-label: external
// ctest-label Npy: unit
#include "compare/engines/external_engine.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/io/npy.h"
#include "engine_test_support.h"
#include "compare/metrics/closed_form.h"
#include "compare/metrics/drape_metric.h"
#include "mysim/wind.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;

using test_support::registryWith;

mysim::Scene scene(const EngineRegistry& registry, const std::string& name) {
  return test_support::shippedScene(registry, name);
}

TEST(ExamplePythonEngine, ReproducesTheVerticalChainClosedFormSag) {
  const EngineRegistry registry = registryWith("examples/external/engines.json");
  const mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  auto run = registry.run("pysim", chain);
  ASSERT_TRUE(run) << run.error().message;
  ASSERT_FALSE(run->blowup);
  const auto error = closedFormError(mysim::buildModel(chain), *run);
  ASSERT_TRUE(error);
  // The same allowance as mysim's (compare/tolerances.json): after 20 s of drag at 1 /s the
  // slowest mode keeps e^-10 of the 0.35 m start displacement, 1.6e-5 m.
  EXPECT_LT(error->error, 1e-4);
}

// The model file's integrator holds the integrator's name and the parameters it declares, and
// nothing else: an outside engine reading "substeps" on an RK4 scene would be misled.
TEST(ModelFile, NamesOnlyTheParametersOfTheIntegratorInUse) {
  const EngineRegistry registry;
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  const mysim::Model model = mysim::buildModel(chain);
  auto keys = [&](const std::string& integrator) {
    chain.integrator.name = integrator;
    const RunConfig config = runConfig(chain);
    const fs::path dir = fs::temp_directory_path() /
                         ("springcheck_model_keys_" + std::to_string(getpid()));
    EXPECT_TRUE(writeModelFile(dir.string(), model, config, framePlan(config.run, false)));
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "model.json"));
    fs::remove_all(dir);
    std::vector<std::string> names;
    for (const auto& [key, value] : j["integrator"].items()) names.push_back(key);
    return names;
  };
  using V = std::vector<std::string>;
  EXPECT_EQ(keys("rk4"), V({"name"}));
  EXPECT_EQ(keys("xpbd"),
            V({"iterations", "max_halvings", "max_iterations", "name", "substeps", "tolerance",
               "warm_start"}));
  EXPECT_EQ(keys("dopri5"), V({"abs_tolerance", "name", "rel_tolerance"}));
  EXPECT_EQ(keys("backward-euler"),
            V({"cg_max_iterations", "cg_preconditioner", "cg_tolerance", "name"}));
  EXPECT_EQ(keys("vbd"),
            V({"acceleration_rho", "iterations", "max_halvings", "max_iterations", "name",
               "tolerance"}));
}

TEST(ModelFile, HoldsEveryParticleSpringFrameTimeAndTheWindTable) {
  const EngineRegistry registry;
  const mysim::Scene windy = scene(registry, "matched/cloth_in_wind.json");
  const mysim::Model model = mysim::buildModel(windy);
  const RunConfig config = runConfig(windy);
  const FramePlan plan = framePlan(config.run, false);
  const fs::path dir =
      fs::temp_directory_path() / ("springcheck_model_" + std::to_string(getpid()));
  ASSERT_TRUE(writeModelFile(dir.string(), model, config, plan));
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "model.json"));
  EXPECT_EQ(j["particles"]["count"], model.particleCount());
  EXPECT_EQ(j["springs"]["count"], model.springs.size());
  EXPECT_EQ(j["springs"]["stiffness"][5].get<double>(), model.springs[5].stiffness);
  EXPECT_EQ(j["frame_times"].size(), plan.times.size());
  EXPECT_EQ(j["frame_steps"].back().get<long>(), mysim::stepCount(config.run));
  auto table = readNpy((dir / "wind.npy").string());
  ASSERT_TRUE(table) << table.error();
  ASSERT_EQ(table->shape.size(), 2u);
  EXPECT_EQ(table->shape[1], model.particleCount());
  // Window 3, particle 20: the table holds the force mysim applies anywhere in that window.
  const mysim::Wind& w = *model.wind;
  const double t = 3.7 * w.gust_period;
  EXPECT_DOUBLE_EQ(table->data[3 * model.particleCount() + 20],
                   mysim::windForce(w, 20, t).dot(w.direction));
  fs::remove_all(dir);
}

TEST(Npy, ReadsWhatItWritesAndRefusesOtherTypes) {
  const fs::path path = fs::temp_directory_path() / ("springcheck_npy_" + std::to_string(getpid()));
  ASSERT_TRUE(writeNpy(path.string(), {2, 3}, {1, 2, 3, 4, 5, 6}).has_value());
  auto a = readNpy(path.string());
  ASSERT_TRUE(a) << a.error();
  EXPECT_EQ(a->shape, (std::vector<long>{2, 3}));
  EXPECT_EQ(a->data[5], 6.0);
  const std::string header = "{'descr': '<i8', 'fortran_order': False, 'shape': (1,), }";
  std::string bytes = std::string("\x93NUMPY\x01\x00", 8);
  bytes += static_cast<char>(header.size());
  bytes += '\0';
  std::ofstream(path, std::ios::binary) << bytes << header << std::string(8, '\0');
  auto bad = readNpy(path.string());
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("float64"), std::string::npos) << bad.error();
  fs::remove(path);
}

// A header that claims far more values than the file holds is refused before anything is
// allocated for them (an 8-byte file claiming 2^34 values once ran out of memory; one claiming
// 10^8 peaked at 771 MiB), and so is a shape whose product overflows; a FIFO is not opened.
TEST(Npy, AClaimedShapeLargerThanTheFileIsRefusedBeforeAllocating) {
  const fs::path path = fs::temp_directory_path() / ("springcheck_npy_big_" + std::to_string(getpid()));
  for (const std::string& shape : {"(17179869184,)", "(100000000,)", "(999999999999, 999999999999)"}) {
    const std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': " + shape + ", }";
    std::string bytes = std::string("\x93NUMPY\x01\x00", 8);
    bytes += static_cast<char>(header.size());
    bytes += '\0';
    std::ofstream(path, std::ios::binary) << bytes << header << std::string(8, '\0');
    auto bad = readNpy(path.string());
    ASSERT_FALSE(bad) << shape;
    EXPECT_TRUE(bad.error().find("shorter than its shape") != std::string::npos ||
                bad.error().find("too large") != std::string::npos)
        << bad.error();
  }
  fs::remove(path);
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  auto fifo = readNpy(path.string());
  ASSERT_FALSE(fifo);
  EXPECT_NE(fifo.error().find("not a regular file"), std::string::npos) << fifo.error();
  fs::remove(path);
}

struct Misbehaviour {
  std::string mode;      // the engine's name in tests/data/misbehaving_engines.json
  std::string expected;  // what the message must say
};

class MisbehavingEngine : public ::testing::TestWithParam<Misbehaviour> {};

TEST_P(MisbehavingEngine, IsRefusedWithAMessageNamingEngineAndFile) {
  const EngineRegistry registry = registryWith("tests/data/misbehaving_engines.json");
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  chain.duration = 0.2;
  auto run = registry.run(GetParam().mode, chain);
  ASSERT_FALSE(run) << GetParam().mode << " was accepted";
  EXPECT_EQ(run.error().kind, EngineError::Kind::Failed);
  EXPECT_NE(run.error().message.find("engine '" + GetParam().mode + "'"), std::string::npos)
      << run.error().message;
  EXPECT_NE(run.error().message.find(GetParam().expected), std::string::npos)
      << run.error().message;
}

INSTANTIATE_TEST_SUITE_P(
    EveryWay, MisbehavingEngine,
    ::testing::Values(Misbehaviour{"exit-code", "exited with code 3"},
                      Misbehaviour{"timeout", "killed at its time limit of 3 s"},
                      Misbehaviour{"wrong-shape", "trajectory.npy: expected shape"},
                      Misbehaviour{"particle-count",
                                   "trajectory.npy: 8 particles, the model has 9"},
                      Misbehaviour{"nan", "trajectory.npy: non-finite value in frame"},
                      Misbehaviour{"short", "declares no blow-up: the run is incomplete"},
                      Misbehaviour{"wrong-times", "times.npy: frame 1 at t"},
                      Misbehaviour{"missing-file", "trajectory.npy: missing"},
                      Misbehaviour{"negative-evaluations",
                                   "derivative_evaluations: expected an integer from 0 to 2^53"},
                      Misbehaviour{"huge-evaluations",
                                   "derivative_evaluations: expected an integer from 0 to 2^53"},
                      Misbehaviour{"blowup-every-frame", "but every frame was returned"},
                      Misbehaviour{"blowup-before-start", "blowup.time: expected a time within"}),
    [](const auto& info) {
      std::string name = info.param.mode;
      std::erase(name, '-');
      return name;
    });

TEST(MisbehavingEngine, ADeclaredBlowUpIsAcceptedAsABlowUpAtItsTime) {
  const EngineRegistry registry = registryWith("tests/data/misbehaving_engines.json");
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  chain.duration = 0.2;
  auto run = registry.run("blowup", chain);
  ASSERT_TRUE(run) << run.error().message;
  ASSERT_TRUE(run->blowup);
  EXPECT_EQ(run->blowup->check, "engine");
  EXPECT_NE(run->blowup->detail.find("the test engine gave up"), std::string::npos);
  // At the declared time (between two frames), not at the step after the last frame.
  EXPECT_NEAR(run->blowup->time, run->times.back() + 0.003, 1e-12);
}

// A declared blow-up whose last frame went non-finite (the engine returned the frame where it
// saw it): accepted as a blow-up at the declared time, that frame dropped, and the record says
// non-finite (it was refused as if nothing had been declared).
TEST(MisbehavingEngine, ADeclaredBlowUpEndingOnANonFiniteFrameSaysNonFinite) {
  const EngineRegistry registry = registryWith("tests/data/misbehaving_engines.json");
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  chain.duration = 0.2;
  auto run = registry.run("blowup-nonfinite-last", chain);
  ASSERT_TRUE(run) << run.error().message;
  ASSERT_TRUE(run->blowup);
  EXPECT_EQ(run->blowup->check, "engine");
  EXPECT_NE(run->blowup->detail.find("position overflowed"), std::string::npos);
  EXPECT_NE(run->blowup->detail.find("non-finite"), std::string::npos) << run->blowup->detail;
  for (const auto& f : run->frames) EXPECT_TRUE(f.allFinite());
}

// A summary.json without the optional counts: evaluations unknown (-1, written as null), not 0,
// and the note says the summary lacks the wall time (not that there is no summary).
TEST(MisbehavingEngine, ASummaryWithoutCountsLeavesThemUnknown) {
  const EngineRegistry registry = registryWith("tests/data/misbehaving_engines.json");
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  chain.duration = 0.2;
  auto run = registry.run("no-evaluations", chain);
  ASSERT_TRUE(run) << run.error().message;
  EXPECT_EQ(run->counts.derivative_evaluations, -1);
  ASSERT_FALSE(run->notes.empty());
  EXPECT_NE(run->notes.front().find("summary.json has no wall_seconds"), std::string::npos)
      << run->notes.front();
}

// An engine that declares single precision carries its floor (half an ulp of float at the run's
// largest coordinate) and says so; its distance from mysim's double-precision run of the same
// algorithm is float round-off: above a tenth of the floor, below a hundred floors.
TEST(DeclaredEngine, AFloat32EngineCarriesItsPrecisionFloorAndSaysSo) {
  const EngineRegistry registry = registryWith("tests/data/declared_engines.json");
  mysim::Scene cloth = scene(registry, "matched/cloth_hanging.json");
  cloth.duration = 0.5;
  auto single = registry.run("pysim-float32", cloth);
  auto own = registry.run("mysim:symplectic-euler", cloth);
  ASSERT_TRUE(single) << single.error().message;
  ASSERT_TRUE(own) << own.error().message;
  // The 1 m cloth's largest coordinate is 1 m at a pinned corner, and the sagging cloth
  // stretches by less than 10 %: the floor is 2^-24 m to 1.1 times that.
  EXPECT_GE(single->precision_floor, std::ldexp(1.0, -24));
  EXPECT_LE(single->precision_floor, 1.1 * std::ldexp(1.0, -24));
  EXPECT_EQ(own->precision_floor, 0.0);
  bool said = false;
  for (const std::string& n : single->notes) said |= n.find("single precision") != std::string::npos;
  EXPECT_TRUE(said);
  const double apart =
      nodeDistance(single->frames.back().leftCols<3>(), own->frames.back().leftCols<3>()).max;
  EXPECT_GT(apart, 0.1 * single->precision_floor);
  EXPECT_LT(apart, 100 * single->precision_floor);
}

// Forces declared independent of time: a scene with wind or driven pins is refused, naming the
// declaration and the scene's field; a scene without either runs.
TEST(DeclaredEngine, ForcesThatIgnoreTimeRefuseWindAndDrivenPins) {
  const EngineRegistry registry = registryWith("tests/data/declared_engines.json");
  for (const auto& [name, field] : {std::pair{"matched/cloth_in_wind.json", "forces.wind"},
                                    {"matched/cloth_driven.json", "forces.pin_motion"}}) {
    auto run = registry.run("pysim-static", scene(registry, name));
    ASSERT_FALSE(run) << name;
    EXPECT_EQ(run.error().kind, EngineError::Kind::Refused);
    EXPECT_NE(run.error().message.find("time_dependent_forces: false"), std::string::npos)
        << run.error().message;
    EXPECT_NE(run.error().message.find(field), std::string::npos) << run.error().message;
  }
  mysim::Scene chain = scene(registry, "matched/chain_hanging.json");
  chain.duration = 0.2;
  auto run = registry.run("pysim-static", chain);
  EXPECT_TRUE(run) << run.error().message;
}

// An engine that does not declare hinges is refused a scene that bends by them (it would run the
// cloth without bending and look merely soft), naming the declaration; the example engine,
// which declares them, runs it.
TEST(DeclaredEngine, AnEngineWithoutHingesRefusesHingeBending) {
  const EngineRegistry registry = registryWith("tests/data/declared_engines.json");
  mysim::Scene strip = scene(registry, "material/cantilever_strip_explicit.json");
  strip.duration = 0.01;
  auto run = registry.run("pysim-static", strip);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().kind, EngineError::Kind::Refused);
  EXPECT_NE(run.error().message.find("\"hinges\": true"), std::string::npos) << run.error().message;
  EXPECT_NE(run.error().message.find("system.material.bending"), std::string::npos)
      << run.error().message;
  const EngineRegistry example = registryWith("examples/external/engines.json");
  auto ran = example.run("pysim", strip);
  EXPECT_TRUE(ran) << ran.error().message;
}

TEST(EnginesFile, MalformedEntriesAreRefusedNamingTheField) {
  const fs::path path =
      fs::temp_directory_path() / ("springcheck_engines_" + std::to_string(getpid()) + ".json");
  struct Case {
    std::string text, expected;
  };
  for (const Case& c : std::vector<Case>{
           {R"({"engines": [{"name": "Bad Name", "command": ["x"]}]})", "engines[0].name"},
           {R"({"engines": [{"name": "a", "command": []}]})", "engines[0].command"},
           {R"({"engines": [{"name": "a", "command": ["x", "{modle}"]}]})",
            "engines[0].command[1]: unknown placeholder {modle}"},
           {R"({"engines": [{"name": "a", "command": ["x"], "time_limit": -1}]})",
            "engines[0].time_limit"},
           {R"({"engines": [{"name": "a", "command": ["x"], "speed": 2}]})", "engines[0].speed"},
           {R"({"engines": [{"name": "mysim", "command": ["x"]}]})", "is taken"},
           {R"({"engines": [{"name": "a", "command": ["x"], "precision": "float16"}]})",
            "engines[0].precision"},
           {R"({"engines": [{"name": "a", "command": ["x"], "time_dependent_forces": "no"}]})",
            "engines[0].time_dependent_forces"},
           {R"({"engines": [{"name": "a", "command": ["x"], "hinges": 1}]})", "engines[0].hinges"},
       }) {
    std::ofstream(path) << c.text;
    EngineRegistry registry;
    auto added = registry.addEnginesFile(path.string());
    ASSERT_FALSE(added) << c.text;
    EXPECT_NE(added.error().find(path.string()), std::string::npos) << added.error();
    EXPECT_NE(added.error().find(c.expected), std::string::npos) << added.error();
  }
  fs::remove(path);
}

}  // namespace
}  // namespace springcheck
