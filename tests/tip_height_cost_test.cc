#include "solver/smooth/cost/tip_height_cost.h"

#include <random>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

TEST(TipHeightCostTest, MeasuresTheContactHeightAlongTheAxis) {
  // Axis +Z (A = 0); contact 0.25 mm above the tip.
  std::array<double, 5> pose = {0, 0, 1, 2, 3};
  std::unique_ptr<ceres::CostFunction> cost(TipHeightCost::Create({5, 5, 3.25}, 0.0, 2.0));
  const double* params[] = {pose.data()};
  double r;
  ASSERT_TRUE(cost->Evaluate(params, &r, nullptr));
  EXPECT_NEAR(r, 0.5, 1e-12);
  std::array<double, 5> tilted = {0.3, 1.1, 1, 2, 3};
  testing::ExpectJacobiansMatchNumeric(TipHeightCost::Create({5, 5, 3.25}, 0.0, 2.0),
                                       {tilted.data()});
}

TEST(TipHeightCostTest, IsZeroWhereTheTipKeepsTheInputsOverhangBelowTheFloor) {
  // The input's tip 2 mm below the floor point along a tilted axis: the
  // cost vanishes there and grows with any slide along the axis.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-1.2, 1.2), coord(-50, 50);
  for (int trial = 0; trial < 20; ++trial) {
    std::array<double, 5> pose = {angle(rng), 3 * angle(rng), coord(rng), coord(rng), coord(rng)};
    if (trial == 0) pose[kPoseA] = 0.0;  // at the pole
    if (trial == 1) pose[kPoseA] = 1e-7;  // next to it
    const Eigen::Vector3d a = PoseAxis(pose.data());
    const Eigen::Vector3d tip = PoseTip(pose.data());
    // Floor point: 2 mm above the tip along the axis and 4 mm sideways.
    const Eigen::Vector3d side = a.unitOrthogonal();
    const Eigen::Vector3d floor_w = tip + 2.0 * a + 4.0 * side;
    std::unique_ptr<ceres::CostFunction> cost(TipHeightCost::Create(floor_w, 2.0, 3.0));
    const double* params[] = {pose.data()};
    double r;
    ASSERT_TRUE(cost->Evaluate(params, &r, nullptr));
    EXPECT_NEAR(r, 0.0, 1e-12);
    std::array<double, 5> slid = pose;
    for (int k = 0; k < 3; ++k) slid[kPoseTip + k] -= 0.5 * a[k];  // 0.5 mm deeper
    const double* slid_params[] = {slid.data()};
    ASSERT_TRUE(cost->Evaluate(slid_params, &r, nullptr));
    EXPECT_NEAR(r, 3.0 * 0.5, 1e-12);
    // The Jacobian away from the zero, where no component vanishes by
    // construction (a relative check cannot judge a zero against 1e-13).
    std::array<double, 5> turned = slid;
    turned[kPoseA] += 0.1;
    turned[kPoseC] -= 0.2;
    testing::ExpectJacobiansMatchNumeric(TipHeightCost::Create(floor_w, 2.0, 3.0),
                                         {turned.data()});
  }
}

}  // namespace
}  // namespace tpopt
