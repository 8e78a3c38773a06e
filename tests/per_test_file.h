#pragma once
// A temporary file of the running test's own: ctest runs a file's tests side by side, each in its
// own process, so a fixed name in testing::TempDir() lets one test write the file while another
// reads it (the ablation tests failed that way now and then).
#include <gtest/gtest.h>

#include <string>

namespace springcheck::test_support {

// TempDir()/STEM_TESTNAME.json
inline std::string perTestJsonPath(const std::string& stem) {
  return testing::TempDir() + "/" + stem + "_" +
         testing::UnitTest::GetInstance()->current_test_info()->name() + ".json";
}

}  // namespace springcheck::test_support
