// The smoother's safety invariants through the whole pipeline: a path
// outside the machine's travel is refused as bad input, and the smoother
// never writes a path that leaves the travel, whatever it would have liked
// to do.
#include <gtest/gtest.h>

#include "model/json_io.h"
#include "model/path_generator.h"
#include "solver/smoothing_pipeline.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

class SafetyInvariantsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(testing::LoadImpellerBench(&surface_, &machine_));
    FlankPathOptions g;
    g.poses = 150;
    g.uv_distortion = 0.03;
    g.axis_noise_deg = 0.3;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &input_).ok());
    cutter_ = *input_.cutter;
  }

  Status Smooth(const Machine& machine, SmoothingMode mode, SmoothingResult* result,
                SmoothingFailure* failure) {
    SmoothingSettings settings;
    settings.mode = mode;
    return RunSmoothing({&input_, &surface_, &cutter_, &machine}, settings, result, failure);
  }

  // The least and greatest value of each joint over `path`.
  std::pair<JointVector, JointVector> JointRange(const ToolPath& path) {
    std::vector<JointVector> joints;
    EXPECT_TRUE(machine_.AssignJoints(path, &joints).ok());
    JointVector lo = joints[0], hi = joints[0];
    for (const JointVector& j : joints) {
      lo = lo.cwiseMin(j);
      hi = hi.cwiseMax(j);
    }
    return {lo, hi};
  }

  RuledSurface surface_;
  Machine machine_;
  ToolPath input_;
  Cutter cutter_;
};

TEST_F(SafetyInvariantsTest, InputOutsideTheTravelIsBadInputNamingPoseAndAxis) {
  const auto [lo, hi] = JointRange(input_);
  Machine narrow = machine_;
  narrow.limits[kX].max = 0.5 * (lo[kX] + hi[kX]);  // half the input's X range
  SmoothingResult result;
  SmoothingFailure failure = SmoothingFailure::kNone;
  const Status s = Smooth(narrow, SmoothingMode::kHighAccuracy, &result, &failure);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(failure, SmoothingFailure::kBadInput);
  EXPECT_NE(s.message().find("pose "), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("X = "), std::string::npos) << s.message();
}

// The travel is set to exactly what the input uses on X, Y, Z and C. The
// high-accuracy smoother wants to go beyond it (checked on the machine
// without those limits; the spline method happens to stay inside here), so
// in each mode it must either stay inside or refuse.
TEST_F(SafetyInvariantsTest, OutputNeverLeavesTheTravel) {
  const auto [lo, hi] = JointRange(input_);
  Machine tight = machine_;
  for (int a : {kX, kY, kZ, kC}) {
    tight.limits[a].min = lo[a] - 1e-6;
    tight.limits[a].max = hi[a] + 1e-6;
  }
  for (SmoothingMode mode : {SmoothingMode::kSpline, SmoothingMode::kHighAccuracy}) {
    SCOPED_TRACE(mode == SmoothingMode::kSpline ? "spline" : "high_accuracy");
    SmoothingResult loose;
    SmoothingFailure failure = SmoothingFailure::kNone;
    ASSERT_TRUE(Smooth(machine_, mode, &loose, &failure).ok());
    const auto [out_lo, out_hi] = JointRange(loose.output);
    bool leaves = false;
    for (int a : {kX, kY, kZ, kC}) {
      leaves = leaves || out_lo[a] < tight.limits[a].min || out_hi[a] > tight.limits[a].max;
    }
    if (mode == SmoothingMode::kHighAccuracy) {
      ASSERT_TRUE(leaves) << "the scenario must tempt the smoother out of the travel";
    }

    SmoothingResult result;
    const Status s = Smooth(tight, mode, &result, &failure);
    if (s.ok()) {
      std::vector<JointVector> joints;
      ASSERT_TRUE(tight.AssignJoints(result.output, &joints).ok());
      EXPECT_TRUE(tight.CheckTravel(result.output, joints).ok());
    } else {
      EXPECT_EQ(failure, SmoothingFailure::kSolver) << s.message();
      EXPECT_NE(s.message().find("travel"), std::string::npos) << s.message();
    }
  }
}

}  // namespace
}  // namespace tpopt
