#include "model/machine/axis_metrics.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

constexpr double kFeedMmPerMin = 600.0;  // 10 mm/s
constexpr double kSpeed = 10.0;

// Tip moving along X at 1 mm per pose, axis tilting with A(s) = k s^p about
// C = 90 deg (axis in the XZ plane). Pivot at the origin, no offsets.
ToolPath PolynomialTiltPath(int n, double k, int p) {
  ToolPath path;
  for (int i = 0; i < n; ++i) {
    ToolPose pose;
    const double s = i;
    pose.p_w_tip = Eigen::Vector3d(s, 0, 0);
    pose.a_w = AnglesToAxis(k * std::pow(s, p), M_PI / 2);
    pose.feed_mm_per_min = kFeedMmPerMin;
    path.poses.push_back(pose);
  }
  return path;
}

MotionReport Evaluate(const Machine& m, const ToolPath& path) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(m.AssignJoints(path, &joints).ok());
  return EvaluateMotion(m, path, joints, MotionOptions());
}

TEST(AxisMetricsTest, QuadraticAngleHasClosedFormDerivatives) {
  const double k = 1e-4;  // rad/mm^2
  const int n = 41;       // s in [0, 40]
  const MotionReport r = Evaluate(Machine(), PolynomialTiltPath(n, k, 2));
  // dA/dt = 2 k s v, peak on the last segment at its midpoint s = 39.5;
  // d2A/dt2 = 2 k v^2 exactly under central differences; jerk 0.
  EXPECT_NEAR(r.axes[kA].peak_velocity, 2 * k * 39.5 * kSpeed, 1e-12);
  EXPECT_NEAR(r.axes[kA].peak_acceleration, 2 * k * kSpeed * kSpeed, 1e-9);
  EXPECT_NEAR(r.axes[kA].peak_jerk, 0.0, 1e-8);
  EXPECT_NEAR(r.axes[kA].peak_second_derivative_per_mm2, 2 * k, 1e-12);
  EXPECT_NEAR(r.axes[kC].peak_velocity, 0.0, 1e-12);
  EXPECT_NEAR(r.machining_time_s, (n - 1) / kSpeed, 1e-12);
  EXPECT_NEAR(r.path_length_mm, n - 1, 1e-12);
  EXPECT_EQ(r.limit_violations, 0);
}

TEST(AxisMetricsTest, CubicAngleHasClosedFormJerk) {
  const double k = 1e-6;
  const MotionReport r = Evaluate(Machine(), PolynomialTiltPath(31, k, 3));
  // Finite differences of a cubic: jerk 6 k v^3 exactly.
  EXPECT_NEAR(r.axes[kA].peak_jerk, 6 * k * std::pow(kSpeed, 3), 1e-9);
}

TEST(AxisMetricsTest, CountsViolationsAgainstLimits) {
  const double k = 1e-4;
  const ToolPath path = PolynomialTiltPath(41, k, 2);
  const double accel = 2 * k * kSpeed * kSpeed;
  Machine m;
  m.limits[kA].max_acceleration = accel * 1.01;
  EXPECT_EQ(Evaluate(m, path).limit_violations, 0);
  m.limits[kA].max_acceleration = accel * 0.99;
  const MotionReport r = Evaluate(m, path);
  // Every interior pose (39 of them) exceeds the limit.
  EXPECT_EQ(r.axes[kA].limit_violations, 39);
  EXPECT_EQ(r.limit_violations, 39);
  EXPECT_GE(r.worst_violation_pose, 1);
  // Travel: with C = 90 deg the Y joint is s cos A, beyond 30 mm for the
  // ten poses s = 31..40.
  Machine travel;
  travel.limits[kY].max = 30;
  EXPECT_EQ(Evaluate(travel, path).axes[kY].limit_violations, 10);
}

TEST(AxisMetricsTest, RapidTakesItsSlowestAxisAndBreaksTheChain) {
  ToolPath path = PolynomialTiltPath(5, 1e-3, 2);
  path.poses[4].rapid = true;
  path.poses[4].p_w_tip = Eigen::Vector3d(3, 50, 0);  // 50 mm in Y
  Machine m;
  m.limits[kY].max_velocity = 25;  // 2 s for the rapid
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  const double t_rapid = SegmentTime(m, path, joints, 3, 1000);
  EXPECT_NEAR(t_rapid, std::abs(joints[4][kY] - joints[3][kY]) / 25, 1e-12);
  const MotionReport r = EvaluateMotion(m, path, joints, MotionOptions());
  EXPECT_NEAR(r.machining_time_s, 3 / kSpeed + t_rapid, 1e-12);
  // The rapid adds time but no feed velocity, acceleration or jerk: the
  // peaks equal those of the path without it.
  ToolPath feed_only = path;
  feed_only.poses.pop_back();
  const MotionReport f = Evaluate(m, feed_only);
  for (int a = 0; a < 5; ++a) {
    EXPECT_EQ(r.axes[a].peak_velocity, f.axes[a].peak_velocity) << a;
    EXPECT_EQ(r.axes[a].peak_acceleration, f.axes[a].peak_acceleration) << a;
    EXPECT_EQ(r.axes[a].peak_jerk, f.axes[a].peak_jerk) << a;
  }
}

// A link (model/path/link_moves.h) is a feed move: timed at its feed and checked
// against the limits like any other. Only the arc-length measure stops at it,
// because the corner where a link meets a cut is the program's, kept as is.
TEST(AxisMetricsTest, ALinkIsAFeedMoveButEndsTheArcLengthStencils) {
  ToolPath path = PolynomialTiltPath(5, 0.0, 1);
  for (int i = 0; i < 5; ++i) {  // A = 0.2 rad, then 0.05 rad/mm from pose 2 on
    path.poses[i].a_w = AnglesToAxis(0.2 + 0.05 * std::max(0, i - 2), M_PI / 2);
  }
  const MotionReport plain = Evaluate(Machine(), path);
  EXPECT_NEAR(plain.axes[kA].peak_second_derivative_per_mm2, 0.05, 1e-12);  // the corner at 2
  path.poses[3].link = true;
  const MotionReport linked = Evaluate(Machine(), path);
  EXPECT_EQ(linked.axes[kA].peak_second_derivative_per_mm2, 0.0);
  EXPECT_EQ(linked.axes[kA].peak_velocity, plain.axes[kA].peak_velocity);
  EXPECT_NEAR(linked.axes[kA].peak_velocity, 0.05 * kSpeed, 1e-12);
  EXPECT_EQ(linked.axes[kA].peak_acceleration, plain.axes[kA].peak_acceleration);
  EXPECT_EQ(linked.machining_time_s, plain.machining_time_s);
}

TEST(AxisMetricsTest, RotaryOnlyMoveReadsFeedAsDegreesPerMinute) {
  ToolPath path;
  for (int i = 0; i < 2; ++i) {
    ToolPose pose;
    pose.a_w = AnglesToAxis(i * 10 * M_PI / 180, 0.0);
    pose.feed_mm_per_min = 600;
    path.poses.push_back(pose);
  }
  Machine m;
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  EXPECT_NEAR(SegmentTime(m, path, joints, 0, 1000), 1.0, 1e-12);  // 10 deg at 10 deg/s
}

}  // namespace
}  // namespace tpopt
