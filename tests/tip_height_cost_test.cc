#include "solver/tip_height_cost.h"

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

TEST(TipHeightCostTest, MeasuresTheContactHeightAlongTheAxis) {
  // Axis +Z (A = 0); contact 0.25 mm above the tip.
  std::array<double, 5> pose = {0, 0, 1, 2, 3};
  std::unique_ptr<ceres::CostFunction> cost(TipHeightCost::Create({5, 5, 3.25}, 2.0));
  const double* params[] = {pose.data()};
  double r;
  ASSERT_TRUE(cost->Evaluate(params, &r, nullptr));
  EXPECT_NEAR(r, 0.5, 1e-12);
  std::array<double, 5> tilted = {0.3, 1.1, 1, 2, 3};
  testing::ExpectJacobiansMatchNumeric(TipHeightCost::Create({5, 5, 3.25}, 2.0), {tilted.data()});
}

}  // namespace
}  // namespace tpopt
