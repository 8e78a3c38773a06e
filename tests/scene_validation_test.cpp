// Malformed scenes are refused with a message naming the file and the field, never a crash.
// This file also runs under the sanitizer preset (ctest label "validation").
// ctest-label: validation,unit
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "mysim/scene_file.h"

namespace mysim {
namespace {

using nlohmann::json;

json validCloth() {
  return json::parse(R"({
    "system": {"type": "cloth", "rows": 4, "cols": 5, "width": 1, "height": 1,
               "particle_mass": 0.01, "structural": {"stiffness": 10}, "pins": "top_corners"},
    "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"name": "rk4", "dt": 0.01, "duration": 1}
  })");
}

json validChain() {
  return json::parse(R"({
    "system": {"type": "chain", "particles": 5, "rest_length": 0.1, "particle_mass": 0.01,
               "stiffness": 100},
    "integrator": {"name": "rk4", "dt": 0.01, "duration": 1}
  })");
}

json validParticles() {
  return json::parse(R"({
    "system": {"type": "particles",
               "particles": [{"position": [0, 0, 0], "mass": 1, "pinned": true},
                             {"position": [1, 0, 0], "mass": 1}],
               "springs": [{"i": 0, "j": 1, "stiffness": 10}]},
    "integrator": {"dt": 0.01, "duration": 1}
  })");
}

struct BadCase {
  std::string name;
  std::function<json()> scene;
  std::string field;     // must appear in the message
  std::string expected;  // and so must this
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

std::string errorFor(const json& scene) {
  auto parsed = parseScene(scene.dump(), "bad.json");
  EXPECT_FALSE(parsed.has_value()) << "accepted: " << scene.dump();
  return parsed ? "" : parsed.error();
}

class MalformedScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(MalformedScene, IsRefusedNamingFileAndField) {
  const BadCase& c = GetParam();
  const std::string message = errorFor(c.scene());
  EXPECT_EQ(message.rfind("bad.json: ", 0), 0u) << message;
  EXPECT_NE(message.find(c.field), std::string::npos) << message;
  EXPECT_NE(message.find(c.expected), std::string::npos) << message;
}

json with(json j, const json::json_pointer& at, json value) {
  j[at] = std::move(value);
  return j;
}
json without(json j, const std::string& parent, const std::string& key) {
  j[json::json_pointer(parent)].erase(key);
  return j;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MalformedScene,
    ::testing::Values(
        BadCase{"MissingSystemType", [] { return without(validCloth(), "/system", "type"); },
                "system.type", "missing"},
        BadCase{"MissingStep", [] { return without(validCloth(), "/integrator", "dt"); },
                "integrator.dt", "missing"},
        BadCase{"NeedsAnUnknownTerm",
                [] { return with(validCloth(), "/needs"_json_pointer, json::array({"bendin"})); },
                "needs[0]", "expected one of bending, damping"},
        BadCase{"NeedsGravityWhichNoAblationTakesOut",
                [] {
                  return with(validCloth(), "/needs"_json_pointer, json::array({"gravity", "wind"}));
                },
                "needs[0]", "unknown model term"},
        BadCase{"NeedsWindWithoutWind",
                [] { return with(validCloth(), "/needs"_json_pointer, json::array({"wind"})); },
                "needs[0]", "the scene does not carry it"},
        BadCase{"MistypedRows", [] { return with(validCloth(), "/system/rows"_json_pointer, "4"); },
                "system.rows", "expected an integer"},
        BadCase{"NanAsString",
                [] { return with(validCloth(), "/system/particle_mass"_json_pointer, "NaN"); },
                "system.particle_mass", "expected a number"},
        BadCase{"NegativeMass",
                [] { return with(validCloth(), "/system/particle_mass"_json_pointer, -1); },
                "system.particle_mass", "> 0"},
        BadCase{"ZeroMass",
                [] { return with(validParticles(), "/system/particles/1/mass"_json_pointer, 0); },
                "system.particles[1].mass", "> 0"},
        BadCase{"ZeroRestLength",
                [] {
                  return with(validParticles(), "/system/springs/0/rest_length"_json_pointer, 0.0);
                },
                "system.springs[0].rest_length", "> 0"},
        BadCase{"CoincidentParticlesGiveZeroDefaultRestLength",
                [] {
                  return with(validParticles(), "/system/particles/1/position"_json_pointer,
                              json::array({0, 0, 0}));
                },
                "system.springs[0].rest_length", "> 0"},
        BadCase{"NegativeStep",
                [] { return with(validCloth(), "/integrator/dt"_json_pointer, -0.01); },
                "integrator.dt", "> 0"},
        BadCase{"ZeroStep", [] { return with(validCloth(), "/integrator/dt"_json_pointer, 0); },
                "integrator.dt", "> 0"},
        BadCase{"SpringToMissingParticle",
                [] { return with(validParticles(), "/system/springs/0/j"_json_pointer, 7); },
                "system.springs[0].j", "[0, 1]"},
        BadCase{
            "EverythingPinned",
            [] { return with(validParticles(), "/system/particles/1/pinned"_json_pointer, true); },
            "system.particles", "every particle is pinned"},
        BadCase{"EveryChainParticlePinned",
                [] {
                  return json::parse(R"({"system": {"type": "chain", "particles": 2,
                    "rest_length": 1, "particle_mass": 1, "stiffness": 1, "pins": [0, 1]},
                    "integrator": {"dt": 0.1, "duration": 1}})");
                },
                "system.pins", "every particle is pinned"},
        BadCase{"PinOutOfRange",
                [] { return with(validCloth(), "/system/pins"_json_pointer, json::array({20})); },
                "system.pins[0]", "[0, 19]"},
        BadCase{"GridTooLargeForMemory",
                [] {
                  json j = validCloth();
                  j["system"]["rows"] = 100000;
                  j["system"]["cols"] = 100000;
                  return j;
                },
                "system", "GiB"},
        BadCase{"ChainTooLargeForMemory",
                [] {
                  json j = validChain();
                  j["system"]["particles"] = 10'000'000;
                  return j;
                },
                "system", "GiB"},
        BadCase{"UnknownField",
                [] { return with(validCloth(), "/system/stifness"_json_pointer, 3); },
                "system.stifness", "unknown field"},
        BadCase{"UnknownIntegrator",
                [] { return with(validCloth(), "/integrator/name"_json_pointer, "leapfrog"); },
                "integrator.name", "unknown integrator 'leapfrog'"},
        BadCase{"UnknownPreconditioner",
                [] {
                  return with(validCloth(), "/integrator/cg_preconditioner"_json_pointer,
                              "multigrid");
                },
                "integrator.cg_preconditioner", "auto, jacobi, block-jacobi, ssor"},
        BadCase{"SecondOrderIntegratorOnCircle",
                [] {
                  return json::parse(R"({"system": {"type": "circle"},
                    "integrator": {"name": "verlet", "dt": 0.1, "duration": 1}})");
                },
                "integrator.name", "first-order"},
        BadCase{"VectorOfWrongLength",
                [] {
                  return with(validCloth(), "/forces/gravity"_json_pointer, json::array({0, -9.8}));
                },
                "forces.gravity", "3 numbers"},
        BadCase{"GustOutOfRange",
                [] {
                  return with(validCloth(), "/forces/wind"_json_pointer,
                              json{{"strength", 1}, {"gust", 2}});
                },
                "forces.wind.gust", "[0, 1]"},
        BadCase{"NullWhereANumberBelongs",
                [] { return with(validCloth(), "/system/width"_json_pointer, nullptr); },
                "system.width", "expected a number, got null"},
        BadCase{"NameLeavesTheOutputFolder",
                [] { return with(validCloth(), "/name"_json_pointer, "../../x"); }, "name",
                "letters, digits"},
        BadCase{"StepGivesMoreStepsThanTheLimit",
                [] { return with(validCloth(), "/integrator/dt"_json_pointer, 1e-320); },
                "integrator.dt", "at most 1e+09"},
        BadCase{"StepLongerThanDuration",
                [] { return with(validCloth(), "/integrator/dt"_json_pointer, 5); },
                "integrator.dt", "no longer than"}),
    [](const auto& info) { return info.param.name; });

TEST(SceneFile, InvalidJsonNamesTheFileAndPosition) {
  auto parsed = parseScene("{\"system\": {\"rows\": NaN}}", "bad.json");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("bad.json: not valid JSON"), std::string::npos);
  EXPECT_NE(parsed.error().find("line 1"), std::string::npos) << parsed.error();
}

// A scene is one JSON value: text after it (a stray brace, a second object) is refused, not
// ignored (the first object was once taken and the rest dropped, exit 0).
TEST(SceneFile, TextAfterTheSceneIsRefusedNamingTheFileAndPosition) {
  const std::string scene = validCloth().dump();
  for (const std::string& text : {scene + " }", scene + "\n" + scene, scene + " x"}) {
    auto parsed = parseScene(text, "two.json");
    ASSERT_FALSE(parsed) << text.substr(scene.size());
    EXPECT_NE(parsed.error().find("two.json: not valid JSON (byte"), std::string::npos)
        << parsed.error();
  }
  EXPECT_TRUE(parseScene(scene + " \n\t", "trailing_space.json"));  // white space is not text
}

// What the plain parser would take or crash on, refused as it is read, naming the field.
TEST(SceneFile, NumberBeyondTheDoubleRangeIsRefusedNamingItsField) {
  std::string text = with(validCloth(), "/system/particle_mass"_json_pointer, 7.75).dump();
  text.replace(text.find("7.75"), 4, "1e400");
  auto parsed = parseScene(text, "bad.json");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("bad.json: system.particle_mass: expected a number within the "
                                "double range"),
            std::string::npos)
      << parsed.error();
}

TEST(SceneFile, DuplicateKeysAreRefusedNotTheLastOneTaken) {
  auto parsed = parseScene(
      R"({"system": {"type": "circle"}, "integrator": {"dt": -1, "dt": 0.04, "duration": 1}})",
      "dup.json");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("dup.json: integrator.dt: given twice"), std::string::npos)
      << parsed.error();
}

TEST(SceneFile, DeepNestingIsRefusedAtTheDepthLimitWithoutRecursing) {
  // 100 000 levels of a wrong type for a field: once a stack overflow while printing it.
  const int depth = 100'000;
  const std::string text = R"({"system": {"type": "chain", "particles": )" +
                           std::string(depth, '[') + std::string(depth, ']') + "}}";
  auto parsed = parseScene(text, "deep.json");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("deep.json: system.particles"), std::string::npos)
      << parsed.error().substr(0, 200);
  EXPECT_NE(parsed.error().find("nested deeper than 64"), std::string::npos);
  EXPECT_LT(parsed.error().size(), 300u);  // the value is not printed
}

TEST(SceneFile, ADirectoryIsRefusedAsNotAFile) {
  auto parsed = loadScene(SPRINGCHECK_SOURCE_DIR "/scenes");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("scenes: is a directory (expected a scene file)"),
            std::string::npos)
      << parsed.error();
}

TEST(SceneFile, MissingFileIsAnError) {
  auto parsed = loadScene("/nonexistent/scene.json");
  ASSERT_FALSE(parsed);
  EXPECT_NE(parsed.error().find("/nonexistent/scene.json"), std::string::npos);
}

TEST(SceneFile, ValidScenesLoadWithTheirDefaults) {
  auto cloth = parseScene(validCloth().dump(), "good.json");
  ASSERT_TRUE(cloth) << cloth.error();
  EXPECT_EQ(cloth->name, "good");
  EXPECT_EQ(std::get<ClothScene>(cloth->system).start.pins, (std::vector<int>{0, 4}));
  EXPECT_FALSE(std::get<ClothScene>(cloth->system).shape.shear.has_value());
  auto particles = parseScene(validParticles().dump(), "p.json");
  ASSERT_TRUE(particles) << particles.error();
  EXPECT_DOUBLE_EQ(std::get<ParticlesScene>(particles->system).springs[0].rest_length, 1.0);  // default: start distance
  EXPECT_EQ(particles->integrator.name, "rk4");
}

TEST(SceneFile, SeedAliasesNameTheSeedIntegrators) {
  for (auto [alias, name] : {std::pair{"e", "euler"}, {"t", "trapezoidal"}, {"r", "rk4"}}) {
    auto scene = parseScene(with(validCloth(), "/integrator/name"_json_pointer, alias).dump(), "a");
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->integrator.name, name);
  }
}

}  // namespace
}  // namespace mysim
