// Engines files: the user's own simulators, declared as commands.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "compare/engines/external_engine.h"
#include "mysim/json_input.h"

namespace springcheck {

namespace {
namespace fs = std::filesystem;

const std::set<std::string>& placeholders() {
  static const std::set<std::string> names = {"model", "out",      "dir",        "python",
                                              "dt",    "duration", "integrator", "scene"};
  return names;
}

constexpr const char* kSchema = "docs/external-engines.md";

// [a-z0-9][a-z0-9._-]*, at most 64 characters: it names folders and table columns.
bool isEngineName(const std::string& name) {
  if (name.empty() || name.size() > 64 || !std::isalnum(static_cast<unsigned char>(name[0]))) {
    return false;
  }
  return std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return (std::isdigit(c) || (c >= 'a' && c <= 'z') || c == '.' || c == '_' || c == '-');
  });
}

// An environment variable's name as a shell writes it: [A-Za-z_][A-Za-z0-9_]*.
bool isEnvironmentName(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(),
                     [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

ExternalEngineSpec readEntry(mysim::FieldReader& r) {
  using mysim::FieldError;
  ExternalEngineSpec spec;
  spec.name = r.text("name");
  if (!isEngineName(spec.name)) {
    throw FieldError{r.field("name"),
                     "'" + spec.name.substr(0, 64) +
                         "': expected lower-case letters, digits, '.', '_' or '-' (at most 64, no "
                         "':'), since it names folders and columns"};
  }
  spec.description = r.text("description", "");
  spec.command = r.textList("command");
  for (std::size_t k = 0; k < spec.command.size(); ++k) {
    const std::string& text = spec.command[k];
    // As the substitution reads it (external_engine.cpp): "{{" and "}}" are literal braces,
    // {env:NAME} an environment variable, anything else in braces must be a known placeholder.
    for (std::size_t at = 0; at < text.size(); ++at) {
      if (text.compare(at, 2, "{{") == 0 || text.compare(at, 2, "}}") == 0) {
        ++at;
        continue;
      }
      if (text[at] != '{') continue;
      const std::size_t close = text.find('}', at);
      if (close == std::string::npos) break;  // a lone brace is the program's business
      const std::string name = text.substr(at + 1, close - at - 1);
      if (name.find('{') != std::string::npos) {
        throw FieldError{r.field("command") + "[" + std::to_string(k) + "]",
                         "a placeholder inside a placeholder ('{" + mysim::clip(name, 40) +
                             "}'): placeholders are replaced in one pass and never nest; write "
                             "each one on its own ({{ and }} for a literal brace)"};
      }
      if (name.starts_with("env:") && !isEnvironmentName(name.substr(4))) {
        throw FieldError{r.field("command") + "[" + std::to_string(k) + "]",
                         "{" + mysim::clip(name, 40) +
                             "}: expected {env:NAME} with NAME letters, digits and '_', not "
                             "starting with a digit"};
      }
      if (!placeholders().count(name) && !name.starts_with("env:")) {
        throw FieldError{r.field("command") + "[" + std::to_string(k) + "]",
                         "unknown placeholder {" + mysim::clip(name, 40) +
                             "} (known: {model} {out} {dir} {python} {dt} {duration} {integrator} "
                             "{scene}, {env:NAME}; {{ and }} for a literal brace)"};
      }
      at = close;
    }
  }
  spec.time_limit = r.positive("time_limit", spec.time_limit);
  spec.precision = r.text("precision", spec.precision);
  if (spec.precision != "float64" && spec.precision != "float32") {
    mysim::failField(r.field("precision"), "\"float64\" or \"float32\"", r.raw("precision"));
  }
  spec.time_dependent_forces = r.boolean("time_dependent_forces", spec.time_dependent_forces);
  spec.hinges = r.boolean("hinges", spec.hinges);
  spec.friction = r.boolean("friction", spec.friction);
  spec.self_collision = r.boolean("self_collision", spec.self_collision);
  r.refuseUnknown(kSchema);
  return spec;
}

}  // namespace

namespace {

std::expected<std::vector<ExternalEngineSpec>, std::string> readEnginesFile(
    const nlohmann::json& root, const std::string& path) {
  const std::string dir = fs::absolute(path).parent_path().lexically_normal().string();
  return mysim::readFields<std::vector<ExternalEngineSpec>>(path, [&] {
    mysim::FieldReader top(root, "");
    std::vector<ExternalEngineSpec> specs;
    std::set<std::string> names;
    top.objects("engines", [&](mysim::FieldReader& entry, std::size_t) {
      ExternalEngineSpec spec = readEntry(entry);
      if (!names.insert(spec.name).second) {
        throw mysim::FieldError{entry.field("name"), "'" + spec.name + "' appears twice"};
      }
      spec.source = path;
      spec.dir = dir;
      specs.push_back(std::move(spec));
    });
    top.refuseUnknown(kSchema);
    return specs;
  });
}

}  // namespace

std::expected<std::vector<ExternalEngineSpec>, std::string> loadEnginesFile(
    const std::string& path) {
  auto root = mysim::readJsonFile(path, "engines file (docs/external-engines.md)");
  if (!root) return std::unexpected(root.error());
  return readEnginesFile(*root, path);
}

std::expected<std::vector<ExternalEngineSpec>, std::string> parseEnginesFile(
    const std::string& text, const std::string& source) {
  auto root = mysim::parseJson(text, source);
  if (!root) return std::unexpected(root.error());
  return readEnginesFile(*root, source);
}

}  // namespace springcheck
