#pragma once
// The command line that is making this process's results, kept beside them so every report
// figure can say how to reproduce it: comparison.json holds it, and a table (a sweep's, a
// stability map's) has it in TABLE.command beside it.
#include <expected>
#include <string>

namespace springcheck {

// Called once by the executable's main: "springcheck" and the arguments as given, each quoted
// for a POSIX shell where it needs to be.
void setInvocation(int argc, char** argv);
// "" when no main set it (the library used directly, the tests).
const std::string& invocation();

// PATH.command beside a table, holding invocation() (nothing when it is empty); and reading it
// back ("" when there is none).
[[nodiscard]] std::expected<void, std::string> writeInvocationBeside(const std::string& path);
std::string invocationBeside(const std::string& path);

}  // namespace springcheck
