// Shared helpers for the GoogleTest suite.
#ifndef TPOPT_TESTS_TEST_UTIL_H_
#define TPOPT_TESTS_TEST_UTIL_H_

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/io/json_io.h"
#include "model/eval/random_cases.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "solver/smooth/tolerance_promise.h"

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

// A tpopt command line: the built program followed by `args`.
inline std::string Tpopt(const std::string& args) { return TpoptBinary() + " " + args; }

// A JSON file the program wrote (a test failure if it is not JSON).
inline nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

// Result of running a shell command: exit code and merged stdout+stderr.
struct CommandResult {
  int exit_code = -1;
  std::string output;
};

// Runs `command` through /bin/sh, capturing stdout and stderr.
inline CommandResult RunCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// A fresh temporary folder, removed with its contents on destruction.
class TempDir {
 public:
  TempDir() {
    char pattern[] = "/tmp/tpopt_test_XXXXXX";
    path_ = mkdtemp(pattern);
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

inline bool FileExists(const std::string& path) { return access(path.c_str(), F_OK) == 0; }

// The whole content of a file ("" if it cannot be read).
inline std::string ReadFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// How often `needle` occurs in `text`, overlaps included.
inline int CountOccurrences(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) {
    ++n;
  }
  return n;
}

// The usual bench: the shared impeller blade on the jcde2022 machine.
inline void LoadImpellerBench(RuledSurface* surface, Machine* machine) {
  ASSERT_TRUE(ReadSurfaceJson(SourcePath("data/surfaces/impeller_blade.json"), surface).ok());
  ASSERT_TRUE(ReadMachineJson(SourcePath("data/machines/jcde2022_ac.json"), machine).ok());
}

// The hypar, whose flank path crosses the A = 0 pole, on the jcde2022 machine.
inline void LoadHyparBench(RuledSurface* surface, Machine* machine) {
  ASSERT_TRUE(ReadSurfaceJson(SourcePath("data/surfaces/hypar.json"), surface).ok());
  ASSERT_TRUE(ReadMachineJson(SourcePath("data/machines/jcde2022_ac.json"), machine).ok());
}

// The two shared machines, data/machines/jcde2022_ac.json and
// linuxcnc_xyzac_trt_sim.json, as the random cases draw them.
inline std::vector<Machine> SharedMachines() {
  std::vector<Machine> machines(2);
  EXPECT_TRUE(ReadMachineJson(SourcePath("data/machines/jcde2022_ac.json"), &machines[0]).ok());
  EXPECT_TRUE(
      ReadMachineJson(SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &machines[1]).ok());
  return machines;
}

// Runs the smoothing pipeline on random case `c`'s CAM path.
inline Status SmoothRandomCase(const RandomCase& c, const SmoothingSettings& settings,
                               SmoothingResult* result) {
  return RunSmoothing({&c.cam_path, &c.surface, &c.cutter, &c.machine}, settings, result);
}

// How far the smoothed path's deviation `after` goes past the tolerance
// promise (solver/smooth/tolerance_promise.h) at its worst grid point, mm:
// max over the grid of |after| - max(tolerance, the input's allowance),
// the allowance from the input path `input` and its deviation `before` on
// the same grid. <= 0 where the promise holds everywhere.
inline double ExcessOverTolerancePromise(const RuledSurface& surface, const ToolPath& input,
                                         const DeviationReport& before,
                                         const DeviationReport& after, double tolerance_mm) {
  const std::vector<double> allowance = InputAllowance(before, CuttingContactU(surface, input));
  double excess = -tolerance_mm;
  for (size_t k = 0; k < after.deviation_mm.size(); ++k) {
    excess = std::max(excess, std::abs(after.deviation_mm[k]) -
                                  std::max(tolerance_mm, allowance[k]));
  }
  return excess;
}

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_TEST_UTIL_H_
