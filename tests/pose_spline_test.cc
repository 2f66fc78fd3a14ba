// Properties of the pose spline (solver/spline/pose_spline.h): it passes through
// every pose it was fitted to (tip and axis), at uneven parameters and on a
// subset of the poses, including poses at and near the A = 0 pole; and it
// reproduces poses whose tip and joints are linear in s between its knots.
#include "solver/spline/pose_spline.h"

#include <gtest/gtest.h>

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
      ASSERT_TRUE(PoseSpline::Fit(path, joints, indices, s, &spline).ok());
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
  ASSERT_TRUE(PoseSpline::Fit(path, joints, indices, s, &spline).ok());
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
  EXPECT_FALSE(PoseSpline::Fit(path, joints, {0, 1, 2, 3}, {0.0, 1.0, 1.0, 2.0}, &spline).ok());
}

}  // namespace
}  // namespace tpopt
