#pragma once
// The python3 springcheck runs its report script and engines files' {python} with, found when it
// is needed, not when springcheck was built: an installed springcheck (a Debian package) must
// work on a machine other than the one that built it.
#include <expected>
#include <string>
#include <vector>

namespace springcheck {

// SPRINGCHECK_PYTHON, when set, is the only candidate (an error if it lacks a module). Otherwise
// the first of: the interpreter the build found, /usr/bin/python3, python3 on PATH, that imports
// every module of `modules`. The error names each candidate and what it lacked, and what to
// install. Found once per process for each set of modules.
[[nodiscard]] std::expected<std::string, std::string> findPython(
    const std::vector<std::string>& modules);

}  // namespace springcheck
