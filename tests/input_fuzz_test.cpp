// A fixed-seed mutation fuzz of every input file we ship: each scene, tolerance file, sweep spec
// and engines file, mutated a few hundred ways (numbers out of range, wrong types, deep nesting,
// duplicate keys, cut and flipped bytes, hostile strings), goes through its loader. Every input
// must be accepted, or refused with a message that starts with its source and says what is
// wrong: never a crash, a hang, an exception or (in the sanitizer build, where CI runs this too) a
// sanitizer report. Accepted scenes are also built into their model.
// ctest-label: validation
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <sstream>

#include "compare/engines/external_engine.h"
#include "compare/studies/sweep.h"
#include "compare/studies/tolerances.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Replacements for a value: the cases that once crashed or slipped through, and their kin.
const std::vector<std::string>& hostileValues() {
  static const std::vector<std::string> values = {"1e400",
                                                  "-1e400",
                                                  "0",
                                                  "-0",
                                                  "-1",
                                                  "1e-320",
                                                  "1e308",
                                                  "4294967297",
                                                  "-9223372036854775809",
                                                  "18446744073709551616",
                                                  "0.5",
                                                  "1e9",
                                                  "1e300",
                                                  "NaN",
                                                  "Infinity",
                                                  "\"x\"",
                                                  "\"\"",
                                                  "\"../../x\"",
                                                  "\"a,b\"",
                                                  "null",
                                                  "true",
                                                  "[]",
                                                  "{}",
                                                  "[1, 2, 3]",
                                                  "{\"a\": 1}",
                                                  std::string(200, '[') + std::string(200, ']'),
                                                  "\"" + std::string(5000, 'z') + "\""};
  return values;
}

// Start and end of every scalar token (number, string, literal) in a JSON text.
std::vector<std::pair<std::size_t, std::size_t>> scalarTokens(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> tokens;
  for (std::size_t k = 0; k < text.size();) {
    const char c = text[k];
    if (c == '"') {
      std::size_t end = k + 1;
      while (end < text.size() && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
      tokens.push_back({k, std::min(end + 1, text.size())});
      k = end + 1;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == 't' || c == 'f' ||
               c == 'n') {
      std::size_t end = k;
      while (end < text.size() && std::string(",]} \n\t").find(text[end]) == std::string::npos) {
        ++end;
      }
      tokens.push_back({k, end});
      k = end;
    } else {
      ++k;
    }
  }
  return tokens;
}

std::string mutate(const std::string& base, std::mt19937_64& random) {
  auto pick = [&](std::size_t n) {
    return static_cast<std::size_t>(random() % std::max<std::size_t>(n, 1));
  };
  std::string text = base;
  const auto tokens = scalarTokens(text);
  switch (pick(7)) {
    case 0:
    case 1: {  // a value replaced by a hostile one
      const auto [start, end] = tokens[pick(tokens.size())];
      text.replace(start, end - start, hostileValues()[pick(hostileValues().size())]);
      break;
    }
    case 2: {  // a key given twice: "key": value repeated right after itself
      const auto [start, end] = tokens[pick(tokens.size())];
      const std::size_t colon = text.find(':', end);
      if (text[start] == '"' && colon == end) {
        const std::size_t value_end = text.find_first_of(",}", colon);
        if (value_end != std::string::npos) {
          text.insert(value_end, ", " + text.substr(start, value_end - start));
        }
      }
      break;
    }
    case 3:  // a cut
      text.resize(pick(text.size()));
      break;
    case 4: {  // a range deleted
      const std::size_t at = pick(text.size()), length = 1 + pick(20);
      text.erase(at, length);
      break;
    }
    case 5: {  // bytes flipped
      for (int k = 0; k < 3; ++k) text[pick(text.size())] ^= static_cast<char>(1 + pick(255));
      break;
    }
    case 6: {  // a value wrapped deep
      const auto [start, end] = tokens[pick(tokens.size())];
      const std::size_t depth = 1 + pick(3000);
      text.insert(end, std::string(depth, ']'));
      text.insert(start, std::string(depth, '['));
      break;
    }
  }
  return text;
}

// The outcome class of a refusal, for the summary.
std::string outcome(const std::string& error, const std::string& source) {
  const std::string rest = error.substr(source.size() + 2);
  for (const char* cls :
       {"not valid JSON", "given twice", "nested deeper", "double range", "unknown field",
        "missing (required)", "unknown scene", "unknown engine", "unknown metric",
        "unknown integrator", "is taken", "placeholder", "GiB", "at most 1e+09"}) {
    if (rest.find(cls) != std::string::npos) return cls;
  }
  if (rest.find("expected") != std::string::npos) return "expected (type or range)";
  return "other";
}

struct FuzzBase {
  std::string kind;  // scene, sweep, tolerances or engines
  fs::path path;
};

// Every input file the project ships of the four kinds a user writes, in path order.
std::vector<FuzzBase> fuzzBases(const fs::path& root) {
  std::vector<FuzzBase> bases;
  for (const auto& e : fs::recursive_directory_iterator(root / "scenes")) {
    if (e.path().extension() == ".json") bases.push_back({"scene", e.path()});
  }
  for (const auto& e : fs::directory_iterator(root / "compare/sweeps"))
    bases.push_back({"sweep", e.path()});
  bases.push_back({"tolerances", root / "compare/tolerances.json"});
  bases.push_back({"tolerances", root / "examples/external/tolerances.json"});
  bases.push_back({"engines", root / "examples/external/engines.json"});
  bases.push_back({"engines", root / "tests/data/misbehaving_engines.json"});
  std::sort(bases.begin(), bases.end(),
            [](const FuzzBase& a, const FuzzBase& b) { return a.path < b.path; });
  return bases;
}

// Reads `text` as its base's kind (a scene is also built into its model); the refusal, if any.
std::optional<std::string> readAs(const FuzzBase& base, const std::string& text,
                                  const std::string& source, EngineRegistry& registry) {
  if (base.kind == "scene") {
    auto scene = mysim::parseScene(text, source, registry.sceneSections());
    if (!scene) return scene.error();
    mysim::buildModel(*scene);
  } else if (base.kind == "sweep") {
    if (auto spec = parseSweepSpec(text, source, registry); !spec) return spec.error();
  } else if (base.kind == "tolerances") {
    auto t = parseTolerances(text, source, base.path.parent_path().string(), registry);
    if (!t) return t.error();
  } else if (auto e = parseEnginesFile(text, source); !e) {
    return e.error();
  }
  return std::nullopt;
}

TEST(InputFuzz, EveryMutatedInputIsAcceptedOrRefusedNamingItsSourceNeverACrash) {
  const std::vector<FuzzBase> bases = fuzzBases(SPRINGCHECK_SOURCE_DIR);
  constexpr int kMutationsPerFile = 500;
  std::mt19937_64 random(20261124);
  std::map<std::string, int> outcomes;
  int inputs = 0, accepted = 0;
  double slowest = 0.0;
  for (const FuzzBase& base : bases) {
    const std::string original = readText(base.path);
    // The mutated text stands in the original's place, so its relative paths resolve.
    const std::string source =
        (base.path.parent_path() / ("fuzz-" + base.path.filename().string())).string();
    for (int m = 0; m < kMutationsPerFile; ++m) {
      const std::string text = mutate(original, random);
      EngineRegistry registry;
      const auto start = std::chrono::steady_clock::now();
      const std::optional<std::string> refusal = readAs(base, text, source, registry);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      slowest = std::max(slowest, seconds);
      ++inputs;
      if (!refusal) {
        ++accepted;
        continue;
      }
      const std::string& error = *refusal;
      ASSERT_EQ(error.rfind(source + ": ", 0), 0u)
          << "refusal does not start with its source: " << error.substr(0, 300);
      EXPECT_LT(error.size(), 1500u) << error.substr(0, 300);
      const std::string cls = outcome(error, source);
      if (cls == "other" && outcomes[base.kind + ": other"] < 2) {
        std::printf("  (an 'other' refusal: %s)\n", error.substr(0, 200).c_str());
      }
      ++outcomes[base.kind + ": " + cls];
    }
  }
  std::printf("fuzz: %d inputs from %zu files, %d accepted, slowest %.3f s\n", inputs, bases.size(),
              accepted, slowest);
  for (const auto& [cls, count] : outcomes) std::printf("  refused, %s: %d\n", cls.c_str(), count);
  EXPECT_GE(inputs, 10000);
  // No input may take long: the loader has no loop an input can stretch (a hang would show here).
  EXPECT_LT(slowest, 5.0);
}

}  // namespace
}  // namespace springcheck
