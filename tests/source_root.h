#pragma once
// The source tree the tests read scenes and data files from (tests/CMakeLists.txt defines
// SPRINGCHECK_SOURCE_DIR). One definition, so test files built as one unity source agree.
#include <string>

namespace springcheck::test {
inline const std::string kRoot = SPRINGCHECK_SOURCE_DIR;
}  // namespace springcheck::test
