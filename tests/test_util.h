// Shared helpers for the GoogleTest suite.
#ifndef TPOPT_TESTS_TEST_UTIL_H_
#define TPOPT_TESTS_TEST_UTIL_H_

#include <memory>
#include <string>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

namespace tpopt::testing {

// Checks an automatically differentiated cost's Jacobians against central
// numeric differences at `parameters`. Takes ownership of `cost`.
inline void ExpectJacobiansMatchNumeric(ceres::CostFunction* cost,
                                        std::vector<double*> parameters,
                                        double relative_precision = 1e-6) {
  std::unique_ptr<ceres::CostFunction> owned(cost);
  ceres::NumericDiffOptions numeric;
  // GradientChecker differentiates with Ridders' method; its default first
  // step (1% of the parameter) would straddle the kink of a one-sided
  // penalty and report a false mismatch.
  numeric.ridders_relative_initial_step_size = 1e-4;
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  ceres::GradientChecker checker(cost, no_manifolds, numeric);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters.data(), relative_precision, &results))
      << results.error_log;
}

// Absolute path of a file in the source tree, e.g. "data/surfaces/hypar.json".
inline std::string SourcePath(const std::string& relative) {
  return std::string(TPOPT_SOURCE_DIR) + "/" + relative;
}

// Absolute path of the built tpopt program.
inline std::string TpoptBinary() { return TPOPT_BINARY; }

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_TEST_UTIL_H_
