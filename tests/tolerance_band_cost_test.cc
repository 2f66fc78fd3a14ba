#include "solver/smooth/cost/tolerance_band_cost.h"

#include <gtest/gtest.h>

#include "model/machine/machine.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

ToleranceBandCost::Band UnitBand() {
  ToleranceBandCost::Band band;
  band.p0_w = {1, 2, 3};
  band.tangent_w = {1, 0, 0};
  band.a0_w = AnglesToAxis(0.3, 0.2);
  band.tolerance_mm = 0.01;
  band.angle_tolerance_rad = 0.5 * M_PI / 180;
  band.margin = 1.0;
  band.step_mm = 0.5;
  return band;
}

TEST(ToleranceBandCostTest, ZeroInsideTheBandAndLinearOutside) {
  const ToleranceBandCost::Band band = UnitBand();
  std::unique_ptr<ceres::CostFunction> cost(ToleranceBandCost::Create(band, 1.0, 0.0));
  // Sliding along the path is free; 0.005 mm off it is inside the band.
  std::array<double, 5> inside = {0.3, 0.2, 1.4, 2.005, 3};
  const double* params[] = {inside.data()};
  double r[3];
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
  // 0.03 mm off the path: excess 0.02 mm = 2 tolerances.
  std::array<double, 5> off = {0.3, 0.2, 1, 2, 3.03};
  params[0] = off.data();
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 2.0, 1e-9);
  // Axis turned by 1 deg in A: outside the 0.5 deg band.
  std::array<double, 5> turned = {0.3 + M_PI / 180, 0.2, 1, 2, 3};
  params[0] = turned.data();
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  const double unit = 1 - std::cos(band.angle_tolerance_rad);
  EXPECT_NEAR(r[1], ((1 - std::cos(M_PI / 180)) - unit) / unit, 1e-6);
}

TEST(ToleranceBandCostTest, JacobiansMatchNumericDifferences) {
  std::array<double, 5> pose = {0.31, 0.25, 1.2, 2.03, 3.02};
  testing::ExpectJacobiansMatchNumeric(ToleranceBandCost::Create(UnitBand(), 0.7, 0.1),
                                       {pose.data()});
}

}  // namespace
}  // namespace tpopt
