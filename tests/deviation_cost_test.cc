#include "solver/smooth/cost/deviation_cost.h"

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

DeviationCost::Settings Settings() {
  DeviationCost::Settings s;
  s.cutter.radius_mm = 4.0;
  s.cutter.flute_length_mm = 40.0;
  s.kinematics.y_offset_mm = 20;
  s.kinematics.z_offset_mm = 10;
  s.tolerance_mm = 0.01;
  s.overcut_factor = 3.0;
  return s;
}

TEST(DeviationCostTest, ResidualIsTheFlankDistanceInTolerances) {
  // Vertical tool at the origin; points at radii 4.02 (undercut 0.02) and
  // 3.99 (overcut 0.01, weighted x3).
  // Guard points count only when inside the cutter.
  DeviationCost::Points points;
  points.contact_w = {{4.02, 0, 5}, {0, -3.99, 12}};
  points.guard_w = {{4.5, 0, 5}, {-3.9, 0, 8}};
  std::unique_ptr<ceres::CostFunction> cost(
      DeviationCost::CreateAtPose(points, Settings(), /*scale=*/1.0));
  std::array<double, 5> pose = {0, 0, 0, 0, 0};  // A = C = 0: axis +Z
  const double* params[] = {pose.data()};
  double r[4];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 2.0, 1e-9);
  EXPECT_NEAR(r[1], -3.0, 1e-9);
  EXPECT_EQ(r[2], 0.0);
  EXPECT_NEAR(r[3], -30.0, 1e-9);
}

TEST(DeviationCostTest, ADeadBandCostsOnlyTheExcessOverIt) {
  // Vertical tool at the origin, band 0.008 mm: undercut 0.02 -> 0.012 mm
  // of excess (1.2 tolerances); overcut 0.01 -> 0.002 (x3: -0.6); 0.005
  // either way is inside the band and costs nothing.
  DeviationCost::Settings settings = Settings();
  settings.dead_band_mm = 0.008;
  DeviationCost::Points points;
  points.contact_w = {{4.02, 0, 5}, {0, -3.99, 12}, {4.005, 0, 7}, {0, 3.995, 9}};
  std::unique_ptr<ceres::CostFunction> cost(
      DeviationCost::CreateAtPose(points, settings, /*scale=*/1.0));
  std::array<double, 5> pose = {0, 0, 0, 0, 0};
  const double* params[] = {pose.data()};
  double r[4];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 1.2, 1e-9);
  EXPECT_NEAR(r[1], -0.6, 1e-9);
  EXPECT_EQ(r[2], 0.0);
  EXPECT_EQ(r[3], 0.0);
  // Outside the band the Jacobian is the plain residual's.
  DeviationCost::Points outside;
  outside.contact_w = {{4.02, 0, 5}};
  testing::ExpectJacobiansMatchNumeric(DeviationCost::CreateAtPose(outside, settings, 1.0),
                                       {pose.data()});
}

TEST(DeviationCostTest, MidMoveUsesJointSpaceInterpolation) {
  // Two poses with the same tip and C turned by 90 deg. The controller
  // moves X, Y, Z, A, C linearly, so mid-move the tip in W is not the
  // programmed tip: it is the forward kinematics of the joint midpoint.
  Machine machine;
  machine.kinematics = Settings().kinematics;
  const double a = 0.3;
  const Eigen::Vector3d tip(1, 2, 3);
  std::array<double, 5> p0 = {a, 0.0, 1, 2, 3}, p1 = {a, M_PI / 2, 1, 2, 3};
  const JointVector mid = 0.5 * (machine.ToJoints(tip, a, 0.0) + machine.ToJoints(tip, a, M_PI / 2));
  Eigen::Vector3d mid_tip, mid_axis;
  machine.ToWorkpiece(mid, &mid_tip, &mid_axis);
  ASSERT_GT((mid_tip - tip).norm(), 0.1);  // the premise: W interpolation would differ
  // A point 4.5 mm from the mid-move axis, 10 mm up it: undercut 0.5 mm.
  const Eigen::Vector3d radial = mid_axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  DeviationCost::Points points;
  points.contact_w = {mid_tip + 10 * mid_axis + 4.5 * radial};
  std::unique_ptr<ceres::CostFunction> cost(
      DeviationCost::CreateBetweenPoses(points, Settings(), 1.0, 0.5));
  const double* params[] = {p0.data(), p1.data()};
  double r[1];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 50.0, 1e-6);
}

TEST(DeviationCostTest, MidMoveInTcpModeKeepsTheTipOnTheChord) {
  // The same two poses as above in TCP mode: mid-move the tip is the
  // programmed tip (linear in W between two equal tips) and the axis that of
  // the mean A, C.
  const double a = 0.3;
  const Eigen::Vector3d tip(1, 2, 3);
  std::array<double, 5> p0 = {a, 0.0, 1, 2, 3}, p1 = {a, M_PI / 2, 1, 2, 3};
  const Eigen::Vector3d mid_axis = AnglesToAxis(a, M_PI / 4);
  const Eigen::Vector3d radial = mid_axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  DeviationCost::Points points;
  points.contact_w = {tip + 10 * mid_axis + 4.5 * radial};
  DeviationCost::Settings settings = Settings();
  settings.interpolation = Interpolation::kTcp;
  std::unique_ptr<ceres::CostFunction> cost(
      DeviationCost::CreateBetweenPoses(points, settings, 1.0, 0.5));
  const double* params[] = {p0.data(), p1.data()};
  double r[1];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 50.0, 1e-6);
  // The joint model puts this point elsewhere relative to its cutter.
  std::unique_ptr<ceres::CostFunction> joint(
      DeviationCost::CreateBetweenPoses(points, Settings(), 1.0, 0.5));
  ASSERT_TRUE(joint->Evaluate(params, r, nullptr));
  EXPECT_GT(std::abs(r[0] - 50.0), 10.0);
  settings.interpolation = Interpolation::kTcp;
  std::array<double, 5> q0 = {0.2, 0.4, 0.1, -0.2, 0.05}, q1 = {0.25, 0.5, 0.3, 0.1, 0.0};
  DeviationCost::Points near;
  near.contact_w = {{4.5, 0.3, 2}, {3.2, -1, 9}};
  testing::ExpectJacobiansMatchNumeric(
      DeviationCost::CreateBetweenPoses(near, settings, 0.7, 0.3), {q0.data(), q1.data()});
}

TEST(DeviationCostTest, JacobiansMatchNumericDifferences) {
  DeviationCost::Points points;
  points.contact_w = {{4.5, 0.3, 2}, {3.2, -1, 9}};
  // Guards outside the cutter (their rows are skipped in plain doubles) and
  // one well inside it (differentiated).
  points.guard_w = {{-2, 4.4, 15}, {1, 4.1, 3}, {0.5, 0.5, 6}};
  std::array<double, 5> p0 = {0.2, 0.4, 0.1, -0.2, 0.05}, p1 = {0.25, 0.5, 0.3, 0.1, 0.0};
  {
    std::unique_ptr<ceres::CostFunction> cost(
        DeviationCost::CreateAtPose(points, Settings(), 0.7));
    const double* params[] = {p0.data()};
    double r[5];
    ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
    EXPECT_LT(r[4], -1.0);  // the premise: the inner guard cuts
  }
  testing::ExpectJacobiansMatchNumeric(DeviationCost::CreateAtPose(points, Settings(), 0.7),
                                       {p0.data()});
  testing::ExpectJacobiansMatchNumeric(
      DeviationCost::CreateBetweenPoses(points, Settings(), 0.7, 0.3), {p0.data(), p1.data()});
}

}  // namespace
}  // namespace tpopt
