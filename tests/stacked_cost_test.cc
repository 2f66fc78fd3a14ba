#include "solver/smooth/cost/stacked_cost.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "solver/smooth/cost/tip_height_cost.h"
#include "solver/smooth/cost/wall_cost.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

std::unique_ptr<ceres::CostFunction> TipHeight(double scale) {
  return std::unique_ptr<ceres::CostFunction>(TipHeightCost::Create({5, 5, 3.25}, 0.4, scale));
}

// Three rows: a cone of 12 deg round an axis the pose below leaves by about
// 20 deg, so that wall acts and its Jacobian is not zero, and the cutter's
// side of the plane z = 0.
std::unique_ptr<ceres::CostFunction> ConeAndSide() {
  WallCost::Walls walls;
  walls.cone.emplace(AnglesToAxis(0.1, 0.3), 12 * M_PI / 180, 2.0);
  walls.side.emplace(
      std::array<SurfaceSideCost::End, 2>{
          SurfaceSideCost::End{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1), 4.0},
          SurfaceSideCost::End{Eigen::Vector3d(0, 30, 0), Eigen::Vector3d(0, 0, 1), 4.0}},
      2.0);
  return std::make_unique<WallCost>(walls);
}

// The stacked block is its parts one after another, value and Jacobian,
// each part evaluated on its own as the truth; PartCost is a part's
// 1/2 |r|^2.
TEST(StackedCostTest, IsThePartsStackedRowByRow) {
  std::array<double, 5> pose = {0.45, 0.9, 1.0, 2.0, 3.0};
  const double* params[] = {pose.data()};
  std::vector<std::unique_ptr<ceres::CostFunction>> alone;
  alone.push_back(TipHeight(2.0));
  alone.push_back(ConeAndSide());
  alone.push_back(TipHeight(0.5));
  StackedCost stacked;
  stacked.Add(TipHeight(2.0));
  stacked.Add(ConeAndSide());
  stacked.Add(TipHeight(0.5));
  ASSERT_EQ(stacked.parts(), 3u);
  ASSERT_EQ(stacked.num_residuals(), 5);
  ASSERT_EQ(stacked.parameter_block_sizes(), std::vector<int32_t>{kPoseSize});

  std::vector<double> r(5), j(5 * kPoseSize);
  double* jacobians[] = {j.data()};
  ASSERT_TRUE(stacked.Evaluate(params, r.data(), jacobians));
  int row = 0;
  for (size_t k = 0; k < alone.size(); ++k) {
    const int rows = alone[k]->num_residuals();
    std::vector<double> rk(rows), jk(rows * kPoseSize);
    double* jacobians_k[] = {jk.data()};
    ASSERT_TRUE(alone[k]->Evaluate(params, rk.data(), jacobians_k));
    double cost = 0.0;
    for (int i = 0; i < rows; ++i) {
      EXPECT_EQ(r[row + i], rk[i]) << k;
      cost += 0.5 * rk[i] * rk[i];
      for (int c = 0; c < kPoseSize; ++c) {
        EXPECT_EQ(j[(row + i) * kPoseSize + c], jk[i * kPoseSize + c]) << k << " " << c;
      }
    }
    EXPECT_GT(cost, 0.0) << k;  // every part acts, so a misplaced row shows
    // (A wall computes its value in double without Jacobians and with Jets
    // with them: the two agree to the last bits, not to every bit.)
    EXPECT_NEAR(stacked.PartCost(k, pose.data()), cost, 1e-12 * cost) << k;
    row += rows;
  }
  // Without Jacobians, and with a constant block's null Jacobian.
  double* no_block[] = {nullptr};
  for (double** jacobians_or_none : {static_cast<double**>(nullptr), no_block}) {
    std::vector<double> r_only(5);
    ASSERT_TRUE(stacked.Evaluate(params, r_only.data(), jacobians_or_none));
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(r_only[i], r[i], 1e-12 * std::abs(r[i])) << i;
  }
  testing::ExpectJacobiansMatchNumeric(
      [] {
        auto* s = new StackedCost;
        s->Add(TipHeight(2.0));
        s->Add(ConeAndSide());
        return s;
      }(),
      {pose.data()});
}

}  // namespace
}  // namespace tpopt
