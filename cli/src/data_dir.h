#pragma once
#include <string>

namespace springcheck {

// Where springcheck finds its own files: the report script, the default scenes, tolerances and
// sweeps. One rule for the build tree and an install: the folder share/springcheck next to the
// executable's folder (PREFIX/bin/springcheck -> PREFIX/share/springcheck;
// build/release/cli/springcheck -> build/release/share/springcheck, links into the source tree
// made by CMake at configure time). The folder keeps the source tree's layout, so the relative
// scene paths inside tolerances and sweep files resolve the same everywhere. The environment
// variable SPRINGCHECK_DATA_DIR overrides it (docs/install.md).
std::string dataDir();
// dataDir() + "/" + relative.
std::string dataFile(const std::string& relative);

}  // namespace springcheck
