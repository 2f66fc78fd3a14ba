#include "solver/smooth/cost/peak_second_cost.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "model/machine/axis_metrics.h"
#include "model/machine/machine.h"

namespace tpopt {
namespace {

using Pose = std::array<double, kPoseSize>;

// The cost's residuals at three poses with caps `cap` and scale 1.
std::array<double, 2> Residuals(const std::array<Pose, 3>& p, const std::array<double, 2>& cap) {
  std::unique_ptr<ceres::CostFunction> cost(PeakSecondCost::Create(cap, 1.0));
  std::array<double, 2> r;
  const double* params[] = {p[0].data(), p[1].data(), p[2].data()};
  EXPECT_TRUE(cost->Evaluate(params, r.data(), nullptr));
  return r;
}

TEST(PeakSecondCostTest, AQuadraticOverUnevenStepsHasItsClosedFormCurvature) {
  // Tips along a line at s = 0, 0.7, 2.0; A = 0.05 s^2 (d2 = 0.1), C
  // linear (d2 = 0). A cap of 0.04 leaves an excess of 0.06: 1.5 caps.
  const std::array<double, 3> s = {0.0, 0.7, 2.0};
  std::array<Pose, 3> p;
  for (int j = 0; j < 3; ++j) p[j] = {0.05 * s[j] * s[j], 0.3 * s[j], 0.6 * s[j], 0.8 * s[j], 0};
  const std::array<double, 2> r = Residuals(p, {0.04, 0.01});
  EXPECT_NEAR(r[0], 1.5, 1e-12);
  EXPECT_EQ(r[1], 0.0);
  // Below the cap, and with no cap, nothing.
  EXPECT_EQ(Residuals(p, {0.2, 0.01})[0], 0.0);
  EXPECT_EQ(Residuals(p, {0.0, 0.0})[0], 0.0);
}

TEST(PeakSecondCostTest, MeasuresTheSecondDerivativeAsTheMotionJudgeDoes) {
  // Three poses on a bent tip path with uneven steps and tilted axes: the
  // judge (EvaluateMotion) reads their joints' peak d2A/ds2 and d2C/ds2; a
  // cap at half of each leaves the cost an excess of exactly one cap.
  ToolPath path;
  const std::vector<Eigen::Vector3d> tips = {{0, 0, 0}, {1.3, 0.2, 0.1}, {1.9, 1.1, 0.3}};
  const std::vector<std::array<double, 2>> angles = {{0.30, 0.10}, {0.34, 0.25}, {0.35, 0.31}};
  for (size_t j = 0; j < tips.size(); ++j) {
    ToolPose pose;
    pose.p_w_tip = tips[j];
    pose.a_w = AnglesToAxis(angles[j][0], angles[j][1]);
    pose.feed_mm_per_min = 600;
    path.poses.push_back(pose);
  }
  const Machine machine;
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  const MotionReport motion = EvaluateMotion(machine, path, joints, MotionOptions());
  const std::array<double, 2> judged = {motion.axes[kA].peak_second_derivative_per_mm2,
                                        motion.axes[kC].peak_second_derivative_per_mm2};
  ASSERT_GT(judged[0], 0.0);
  ASSERT_GT(judged[1], 0.0);
  std::array<Pose, 3> p;
  for (int j = 0; j < 3; ++j) {
    p[j] = {joints[j][kA], joints[j][kC], tips[j].x(), tips[j].y(), tips[j].z()};
  }
  const std::array<double, 2> r = Residuals(p, {judged[0] / 2, judged[1] / 2});
  EXPECT_NEAR(r[0], 1.0, 1e-9);
  EXPECT_NEAR(r[1], 1.0, 1e-9);
}

TEST(PeakSecondCostTest, StandingTipsHaveNoCurvature) {
  std::array<Pose, 3> p = {Pose{0.1, 0, 1, 2, 3}, Pose{0.5, 0, 1, 2, 3}, Pose{0.2, 0, 2, 2, 3}};
  const std::array<double, 2> r = Residuals(p, {1e-6, 1e-6});
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
}

}  // namespace
}  // namespace tpopt
