#include "solver/smooth/cost/axis_limit_cost.h"

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(AxisLimitCostTest, ZeroInsideAndLinearExcessOutside) {
  // C turns 0.1 rad in 1 s: 0.1 rad/s against a 0.08 rad/s limit, margin 1.
  std::array<double, 5> p0 = {0.3, 0.0, 0, 0, 0}, p1 = {0.3, 0.1, 0, 0, 0};
  const std::array<double, 5> limits = {kInf, kInf, kInf, kInf, 0.08};
  std::unique_ptr<ceres::CostFunction> cost(
      AxisLimitCost<1>::Create({0.0, 1.0}, limits, KinematicParams(), 1.0, 1.0));
  const double* params[] = {p0.data(), p1.data()};
  double r[5];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[kC], (0.1 - 0.08) / 0.08, 1e-12);
  for (int a : {kX, kY, kZ, kA}) EXPECT_EQ(r[a], 0.0);
  const std::array<double, 5> loose = {kInf, kInf, kInf, kInf, 0.2};
  std::unique_ptr<ceres::CostFunction> inside(
      AxisLimitCost<1>::Create({0.0, 1.0}, loose, KinematicParams(), 1.0, 1.0));
  ASSERT_TRUE(inside->Evaluate(params, r, nullptr));
  EXPECT_EQ(r[kC], 0.0);
}

TEST(AxisLimitCostTest, MachineAxesGoThroughTheKinematics) {
  // Same tip, C turned: with the table rotating, the X, Y joints move even
  // though the tip in W does not. Tip (10, 0, 0), C 0 -> 0.1 rad in 1 s.
  std::array<double, 5> p0 = {0.0, 0.0, 10, 0, 0}, p1 = {0.0, 0.1, 10, 0, 0};
  const std::array<double, 5> limits = {1e-3, 1e-3, kInf, kInf, kInf};
  std::unique_ptr<ceres::CostFunction> cost(
      AxisLimitCost<1>::Create({0.0, 1.0}, limits, KinematicParams(), 1.0, 1.0));
  const double* params[] = {p0.data(), p1.data()};
  double r[5];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  // X = cos(C) * 10 - 10, Y = sin(C) * 10 (A = 0).
  EXPECT_NEAR(r[kX], (10 * (1 - std::cos(0.1)) - 1e-3) / 1e-3, 1e-6);
  EXPECT_NEAR(r[kY], (10 * std::sin(0.1) - 1e-3) / 1e-3, 1e-6);
}

TEST(AxisLimitCostTest, JacobiansMatchNumericDifferencesOutsideTheLimit) {
  KinematicParams k;
  k.y_offset_mm = 20;
  k.z_offset_mm = 10;
  std::array<double, 5> p0 = {0.3, 0.1, 5, 6, 7}, p1 = {0.35, 0.2, 5.5, 6.1, 7},
                        p2 = {0.42, 0.35, 6.2, 6.1, 7.3}, p3 = {0.5, 0.6, 7, 6, 7.5};
  const std::array<double, 5> limits = {0.1, 0.1, 0.1, 0.01, 0.01};
  testing::ExpectJacobiansMatchNumeric(AxisLimitCost<1>::Create({0, 1}, limits, k, 2.0, 0.9),
                                       {p0.data(), p1.data()});
  testing::ExpectJacobiansMatchNumeric(
      AxisLimitCost<2>::Create({0, 1, 2.5}, limits, k, 2.0, 0.9),
      {p0.data(), p1.data(), p2.data()});
  testing::ExpectJacobiansMatchNumeric(
      AxisLimitCost<3>::Create({0, 1, 2.5, 3}, limits, k, 2.0, 0.9),
      {p0.data(), p1.data(), p2.data(), p3.data()});
}

}  // namespace
}  // namespace tpopt
