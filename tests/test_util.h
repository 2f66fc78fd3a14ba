// Shared helpers for the GoogleTest suite.
#ifndef TPOPT_TESTS_TEST_UTIL_H_
#define TPOPT_TESTS_TEST_UTIL_H_

#include <string>

namespace tpopt::testing {

// Absolute path of a file in the source tree, e.g. "data/surfaces/hypar.json".
inline std::string SourcePath(const std::string& relative) {
  return std::string(TPOPT_SOURCE_DIR) + "/" + relative;
}

// Absolute path of the built tpopt program.
inline std::string TpoptBinary() { return TPOPT_BINARY; }

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_TEST_UTIL_H_
