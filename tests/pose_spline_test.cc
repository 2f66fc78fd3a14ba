// Properties of the pose spline (solver/spline/pose_spline.h): it passes through
// every pose it was fitted to (tip and axis), at uneven parameters and on a
// subset of the poses, including poses at and near the A = 0 pole; and it
// reproduces poses whose tip and joints are linear in s between its knots.
#include "solver/spline/pose_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace tpopt {
namespace {

Machine SimMachine() {
  Machine m;
  m.kinematics.y_offset_mm = 20.0;
  m.kinematics.z_offset_mm = 10.0;
  return m;
}

// A path of n poses with tip and (A, C) drawn at random near a smooth
// sweep; poses 3 and 4 at A = 0 and A = 1e-4 rad.
void RandomPath(int n, unsigned seed, ToolPath* path, std::vector<JointVector>* joints) {
  const Machine machine = SimMachine();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-1, 1);
  for (int i = 0; i < n; ++i) {
    const double a = i == 3 ? 0.0 : i == 4 ? 1e-4 : 0.3 + 0.02 * i + 0.05 * jitter(rng);
    const double c = -1.0 + 0.05 * i + 0.1 * jitter(rng);
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(2.0 * i + jitter(rng), 5 * jitter(rng), 3 * jitter(rng));
    pose.a_w = AnglesToAxis(a, c);
    path->poses.push_back(pose);
    joints->push_back(machine.ToJoints(pose.p_w_tip, a, c));
  }
}

TEST(PoseSplinePropertyTest, PassesThroughItsKnotsAtUnevenParameters) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    ToolPath path;
    std::vector<JointVector> joints;
    RandomPath(30, seed, &path, &joints);
    std::mt19937 rng(100 + seed);
    std::uniform_real_distribution<double> gap(0.1, 3.0);
    // Every pose, then every other pose plus the last.
    for (int stride : {1, 2}) {
      std::vector<size_t> indices;
      for (size_t i = 0; i < path.poses.size(); i += stride) indices.push_back(i);
      if (indices.back() != path.poses.size() - 1) indices.push_back(path.poses.size() - 1);
      std::vector<double> s = {gap(rng)};
      while (s.size() < indices.size()) s.push_back(s.back() + gap(rng));
      PoseSpline spline;
      ASSERT_TRUE(
          PoseSpline::Fit(path, joints, indices, s, PoseSpline::Ends::kNatural, &spline).ok());
      for (size_t k = 0; k < indices.size(); ++k) {
        const ToolPose& want = path.poses[indices[k]];
        ToolPose got;
        spline.Evaluate(s[k], &got);
        const std::string where = "seed " + std::to_string(seed) + ", stride " +
                                  std::to_string(stride) + ", knot " + std::to_string(k);
        EXPECT_LT((got.p_w_tip - want.p_w_tip).norm(), 1e-9) << where;
        EXPECT_LT((got.a_w - want.a_w).norm(), 1e-9) << where;
      }
    }
  }
}

TEST(PoseSplinePropertyTest, ReproducesPosesLinearInTheParameterBetweenKnots) {
  const Machine machine = SimMachine();
  ToolPath path;
  std::vector<JointVector> joints;
  auto tip = [](double s) { return Eigen::Vector3d(1.0 + 2.0 * s, -3.0 + 0.5 * s, 4.0 - s); };
  auto a_of = [](double s) { return 0.2 + 0.01 * s; };
  auto c_of = [](double s) { return -0.5 + 0.03 * s; };
  const std::vector<double> s = {0.0, 0.4, 1.5, 1.7, 3.2, 5.0, 5.1, 8.0};  // uneven
  std::vector<size_t> indices;
  for (size_t i = 0; i < s.size(); ++i) {
    ToolPose pose;
    pose.p_w_tip = tip(s[i]);
    pose.a_w = AnglesToAxis(a_of(s[i]), c_of(s[i]));
    path.poses.push_back(pose);
    // Only the joints' A and C are read; X, Y, Z come from the tips.
    joints.push_back(machine.ToJoints(pose.p_w_tip, a_of(s[i]), c_of(s[i])));
    indices.push_back(i);
  }
  PoseSpline spline;
  ASSERT_TRUE(PoseSpline::Fit(path, joints, indices, s, PoseSpline::Ends::kNatural, &spline).ok());
  for (double t = 0.0; t <= 8.0; t += 0.05) {
    ToolPose got;
    spline.Evaluate(t, &got);
    EXPECT_LT((got.p_w_tip - tip(t)).norm(), 1e-9) << "s " << t;
    EXPECT_LT((got.a_w - AnglesToAxis(a_of(t), c_of(t))).norm(), 1e-9) << "s " << t;
  }
}

TEST(PoseSplinePropertyTest, RefusesParametersThatDoNotIncrease) {
  ToolPath path;
  std::vector<JointVector> joints;
  RandomPath(4, 9, &path, &joints);
  PoseSpline spline;
  EXPECT_FALSE(PoseSpline::Fit(path, joints, {0, 1, 2, 3}, {0.0, 1.0, 1.0, 2.0},
                               PoseSpline::Ends::kNatural, &spline)
                   .ok());
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

// Tips at steps of 5 mm (3-4-0), 0 mm (the axis only turns) and 13 mm
// (5-12-0).
std::vector<ToolPose> StepsOf5And0And13() {
  std::vector<ToolPose> poses(4);
  poses[1].p_w_tip = Eigen::Vector3d(3, 4, 0);
  poses[2].p_w_tip = poses[1].p_w_tip;
  poses[2].a_w = AnglesToAxis(0.2, 0.1);
  poses[3].p_w_tip = poses[2].p_w_tip + Eigen::Vector3d(5, 12, 0);
  return poses;
}

// The one tip arc length, with either caller's least step: an absolute
// one (the spline method's) and one scaled to the mean step (the
// coarse-to-fine stations'); a standing pose gets exactly the floor.
TEST(TipArcLengthTest, StepsAreTheTipDistancesWithTheFloorForAStandingPose) {
  const std::vector<ToolPose> poses = StepsOf5And0And13();
  std::vector<double> s = TipArcLength(poses.data(), poses.size(), {1e-6, 0.0});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0], 0.0);
  EXPECT_DOUBLE_EQ(s[1], 5.0);
  EXPECT_DOUBLE_EQ(s[2], 5.0 + 1e-6);
  EXPECT_DOUBLE_EQ(s[3], 18.0 + 1e-6);
  // Mean step 18 / 3 = 6 mm: the floor is 6e-6 mm, above the 1e-9 given.
  s = TipArcLength(poses.data(), poses.size(), {1e-9, 1e-6});
  EXPECT_DOUBLE_EQ(s[1], 5.0);
  EXPECT_DOUBLE_EQ(s[2], 5.0 + 6e-6);
  EXPECT_DOUBLE_EQ(s[3], 18.0 + 6e-6);
  // All standing: the mean is 0, and the absolute floor holds.
  std::vector<ToolPose> standing(3);
  s = TipArcLength(standing.data(), standing.size(), {1e-9, 1e-6});
  EXPECT_DOUBLE_EQ(s[1], 1e-9);
  EXPECT_DOUBLE_EQ(s[2], 2e-9);
  EXPECT_TRUE(TipArcLength(poses.data(), 0, {1e-6, 0.0}).empty());
  EXPECT_EQ(TipArcLength(poses.data(), 1, {1e-6, 0.0}), std::vector<double>{0.0});
}

TEST(TipArcLengthTest, EachStepIsTheLargerOfTheTipDistanceAndTheFloorOnRandomPaths) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    ToolPath path;
    std::vector<JointVector> joints;
    RandomPath(40, seed, &path, &joints);
    path.poses[7].p_w_tip = path.poses[6].p_w_tip;  // one standing pose
    for (const ArcLengthStepFloor floor : {ArcLengthStepFloor{1e-6, 0.0},
                                           ArcLengthStepFloor{1e-9, 1e-6}}) {
      const std::vector<double> s = TipArcLength(path.poses.data(), path.poses.size(), floor);
      double total = 0.0;
      for (size_t i = 1; i < path.poses.size(); ++i) {
        total += (path.poses[i].p_w_tip - path.poses[i - 1].p_w_tip).norm();
      }
      const double floor_mm =
          std::max(floor.min_step_mm, floor.of_mean_step * total / (path.poses.size() - 1));
      for (size_t i = 1; i < s.size(); ++i) {
        const double d = (path.poses[i].p_w_tip - path.poses[i - 1].p_w_tip).norm();
        EXPECT_NEAR(s[i] - s[i - 1], std::max(d, floor_mm), 1e-12) << seed << " " << i;
      }
      EXPECT_GT(s[7] - s[6], 0.0);
    }
  }
}

}  // namespace
}  // namespace tpopt
