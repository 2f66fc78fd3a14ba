#include "solver/smooth/cost/tip_slide_cost.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/test_util.h"

namespace tpopt {
namespace {

TEST(TipSlideCostTest, MeasuresOnlyTheSlideAlongThePath) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-1.2, 1.2), coord(-50, 50);
  for (int trial = 0; trial < 20; ++trial) {
    const std::array<double, 5> at_start = {angle(rng), 3 * angle(rng), coord(rng), coord(rng),
                                            coord(rng)};
    const Eigen::Vector3d start = PoseTip(at_start.data());
    const Eigen::Vector3d along = Eigen::Vector3d(coord(rng), coord(rng), coord(rng)).normalized();
    const Eigen::Vector3d across = along.unitOrthogonal();
    std::unique_ptr<ceres::CostFunction> cost(TipSlideCost::Create(start, along, 4.0));
    double r;
    // At the start, whatever the axis: zero.
    std::array<double, 5> turned = at_start;
    turned[kPoseA] += 0.4;
    turned[kPoseC] -= 1.3;
    for (const std::array<double, 5>& pose : {at_start, turned}) {
      const double* params[] = {pose.data()};
      ASSERT_TRUE(cost->Evaluate(params, &r, nullptr));
      EXPECT_NEAR(r, 0.0, 1e-12);
    }
    // 0.3 mm sideways and 0.02 mm along: the scale times the 0.02 mm alone.
    std::array<double, 5> moved = at_start;
    for (int k = 0; k < 3; ++k) moved[kPoseTip + k] += 0.3 * across[k] + 0.02 * along[k];
    const double* moved_params[] = {moved.data()};
    ASSERT_TRUE(cost->Evaluate(moved_params, &r, nullptr));
    EXPECT_NEAR(r, 4.0 * 0.02, 1e-12);
    testing::ExpectJacobiansMatchNumeric(TipSlideCost::Create(start, along, 4.0), {moved.data()});
  }
}

}  // namespace
}  // namespace tpopt
