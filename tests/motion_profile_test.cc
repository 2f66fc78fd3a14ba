#include "apps/motion_profile.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "model/machine/axis_metrics.h"
#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

double PeakAbs(const std::vector<double>& values) {
  double peak = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) peak = std::max(peak, std::abs(v));
  }
  return peak;
}

// The plots must show what the report's peaks measure.
TEST(MotionProfileTest, PeaksAgreeWithTheMotionMetricsAndRapidsAreGaps) {
  RuledSurface surface;
  ASSERT_TRUE(
      ReadSurfaceJson(testing::SourcePath("data/surfaces/impeller_blade.json"), &surface).ok());
  Machine machine;
  ASSERT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"),
                              &machine)
                  .ok());
  FlankPathOptions options;
  options.poses = 80;
  options.uv_distortion = 0.03;
  options.axis_noise_deg = 0.3;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(surface, options, &path).ok());
  path.poses[40].rapid = true;  // a gap in the velocity and acceleration

  MotionProfile profile;
  ASSERT_TRUE(ComputeMotionProfile(machine, path, 1000.0, &profile).ok());
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  MotionOptions motion;
  const MotionReport report = EvaluateMotion(machine, path, joints, motion);

  const size_t n = path.poses.size();
  ASSERT_EQ(profile.s_pose_mm.size(), n);
  ASSERT_EQ(profile.s_segment_mm.size(), n - 1);
  EXPECT_TRUE(std::is_sorted(profile.s_pose_mm.begin(), profile.s_pose_mm.end()));
  for (int k = 0; k < 2; ++k) {
    const int axis = k == 0 ? kA : kC;
    EXPECT_NEAR(PeakAbs(profile.velocity_deg_s[k]),
                report.axes[axis].peak_velocity * kRadToDeg, 1e-9);
    EXPECT_NEAR(PeakAbs(profile.acceleration_deg_s2[k]),
                report.axes[axis].peak_acceleration * kRadToDeg, 1e-9);
    EXPECT_NEAR(profile.angle_deg[k][7], joints[7][axis] * kRadToDeg, 1e-12);
    EXPECT_TRUE(std::isnan(profile.velocity_deg_s[k][39]));      // the rapid into pose 40
    EXPECT_TRUE(std::isnan(profile.acceleration_deg_s2[k][40]));  // next to it
  }
}

}  // namespace
}  // namespace tpopt
