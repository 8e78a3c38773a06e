// An engines file's command placeholders (compare/engines/external_engine.h): substituted once,
// left to right, so a value that holds placeholder text stays text (a folder named "{dir}", a
// TMPDIR holding "{out}" once looped for ever); {env:NAME} and literal braces.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cstdlib>

#include "compare/engines/external_engine.h"

namespace springcheck {
namespace {

const std::vector<std::pair<std::string, std::string>> kValues = {
    {"{model}", "/scratch/{out}/model.json"}, {"{out}", "/scratch/{out}/out"}, {"{dir}", "/a/{dir}"}};

TEST(Placeholders, AValueHoldingPlaceholderTextIsNotSubstitutedAgain) {
  EXPECT_EQ(substitutePlaceholders("{dir}/engine.py", kValues).value(), "/a/{dir}/engine.py");
  EXPECT_EQ(substitutePlaceholders("--out={out}", kValues).value(), "--out=/scratch/{out}/out");
  EXPECT_EQ(substitutePlaceholders("{model}{out}", kValues).value(),
            "/scratch/{out}/model.json/scratch/{out}/out");
}

TEST(Placeholders, DoubledBracesAreLiteralBraces) {
  EXPECT_EQ(substitutePlaceholders("{{model}}", kValues).value(), "{model}");
  EXPECT_EQ(substitutePlaceholders("x{{}}y", kValues).value(), "x{}y");
}

TEST(Placeholders, EnvReadsTheEnvironmentOrNamesWhatIsMissing) {
  setenv("SPRINGCHECK_PLACEHOLDER_TEST", "/opt/sim", 1);
  EXPECT_EQ(substitutePlaceholders("{env:SPRINGCHECK_PLACEHOLDER_TEST}/bin/sim", kValues).value(),
            "/opt/sim/bin/sim");
  unsetenv("SPRINGCHECK_PLACEHOLDER_TEST");
  auto missing = substitutePlaceholders("{env:SPRINGCHECK_PLACEHOLDER_TEST}/bin", kValues);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("SPRINGCHECK_PLACEHOLDER_TEST"), std::string::npos);
}

TEST(Placeholders, TheEnginesFileAcceptsEnvAndBracesAndRefusesAnUnknownOne) {
  const std::string ok = R"({"engines": [{"name": "e", "command": ["{env:HOME}/sim", "{{x}}", "{model}"]}]})";
  EXPECT_TRUE(parseEnginesFile(ok, "engines.json"));
  const std::string bad = R"({"engines": [{"name": "e", "command": ["{modle}"]}]})";
  auto refused = parseEnginesFile(bad, "engines.json");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("{modle}"), std::string::npos) << refused.error();
  EXPECT_NE(refused.error().find("engines.json"), std::string::npos) << refused.error();
}

// A placeholder inside another ({env:{dir}}) cannot mean anything in a one-pass substitution: it
// is refused when the engines file is read (exit 2, naming the entry), not at run time (it was
// read as the variable "{dir" and failed every run with exit 4); so is an impossible variable name.
TEST(Placeholders, ANestedPlaceholderIsRefusedWhenTheEnginesFileIsRead) {
  for (const char* command : {"{env:{dir}}/sim", "{dir{out}}", "{env:9LIVES}", "{env:A-B}"}) {
    const std::string text = std::string(R"({"engines": [{"name": "e", "command": [")") + command +
                             R"("]}]})";
    auto refused = parseEnginesFile(text, "engines.json");
    ASSERT_FALSE(refused) << command;
    EXPECT_NE(refused.error().find("engines.json: engines[0].command[0]"), std::string::npos)
        << refused.error();
  }
}

}  // namespace
}  // namespace springcheck
