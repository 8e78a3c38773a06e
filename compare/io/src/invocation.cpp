#include "compare/io/invocation.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compare/io/atomic_file.h"

namespace springcheck {
namespace {

std::string& stored() {
  static std::string command;
  return command;
}

// An argument as a shell reads it back: bare if it holds only safe characters, else in single
// quotes (a quote inside as '\'').
std::string quoted(const std::string& arg) {
  const bool safe = !arg.empty() && arg.find_first_not_of(
                                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=:,+@%") == std::string::npos;
  if (safe) return arg;
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void setInvocation(int argc, char** argv) {
  std::string command = "springcheck";
  for (int k = 1; k < argc; ++k) command += " " + quoted(argv[k]);
  stored() = command;
}

const std::string& invocation() { return stored(); }

std::expected<void, std::string> writeInvocationBeside(const std::string& path) {
  if (invocation().empty()) return {};
  return writeFileAtomically(path + ".command", [](std::ostream& out) { out << invocation() << '\n'; });
}

std::string invocationBeside(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path + ".command", ec)) return "";
  std::ifstream in(path + ".command");
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace springcheck
