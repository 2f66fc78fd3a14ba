#include "solver/smooth/cost/axis_cone_cost.h"

#include <gtest/gtest.h>

#include <random>

#include "model/machine/machine.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

double Residual(ceres::CostFunction* cost, const std::array<double, 5>& pose) {
  const double* params[] = {pose.data()};
  double r = -1;
  EXPECT_TRUE(cost->Evaluate(params, &r, nullptr));
  return r;
}

TEST(AxisConeCostTest, ZeroInsideTheConeAndTheClosedFormOutside) {
  // Starting axis at A = 0.4 rad, C = 1; the cone 10 deg. An axis turned by
  // an angle g in A (C fixed) is g from the start (same plane).
  const double cone = 10 * M_PI / 180;
  const Eigen::Vector3d a0 = AnglesToAxis(0.4, 1.0);
  std::unique_ptr<ceres::CostFunction> cost(
      AxisConeCost::Create(a0, cone, 2.0));
  for (double g_deg :
       {0.0, 5.0, 9.9, 10.5, 20.0, 60.0, 180.0 - 2 * 0.4 * 180 / M_PI}) {
    const double g = g_deg * M_PI / 180;
    const double expected =
        g <= cone ? 0.0
                  : 2.0 * ((1 - std::cos(g)) - (1 - std::cos(cone))) /
                        (1 - std::cos(cone));
    EXPECT_NEAR(Residual(cost.get(), {0.4 + g, 1.0, 0, 0, 0}), expected, 1e-9)
        << g_deg;
  }
  // The flipped axis (A, C) -> (-A, C + pi) is the same axis: no cost.
  EXPECT_NEAR(Residual(cost.get(), {-0.4, 1.0 + M_PI, 5, 6, 7}), 0.0, 1e-12);
  // The reversed axis, the worst: 2 / (1 - cos theta) - 1 units.
  EXPECT_NEAR(Residual(cost.get(), {M_PI - 0.4, 1.0 + M_PI, 0, 0, 0}),
              2.0 * (2 - (1 - std::cos(cone))) / (1 - std::cos(cone)), 1e-9);
}

TEST(AxisConeCostTest,
     JacobiansMatchNumericDifferencesAtRandomPosesAndNearThePole) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1.5, 1.5);
  const double cone = 12 * M_PI / 180;
  for (int trial = 0; trial < 20; ++trial) {
    // The start at the pole (A = 0) or next to it for the first trials.
    const double a0_a = trial == 0 ? 0.0 : trial == 1 ? 1e-6 : angle(rng);
    const Eigen::Vector3d a0 = AnglesToAxis(a0_a, 2 * angle(rng));
    // A pose outside the cone (where the wall acts) 15-40 deg away.
    const double away = (15 + 25 * std::abs(angle(rng)) / 1.5) * M_PI / 180;
    std::array<double, 5> pose = {a0_a + away, 2 * angle(rng), 1, 2, 3};
    std::unique_ptr<ceres::CostFunction> probe(
        AxisConeCost::Create(a0, cone, 1.5));
    const Eigen::Vector3d a = AnglesToAxis(pose[0], pose[1]);
    if (std::acos(std::clamp(a.dot(a0), -1.0, 1.0)) <= cone + 1e-3) continue;
    EXPECT_GT(Residual(probe.get(), pose), 0.0);
    testing::ExpectJacobiansMatchNumeric(AxisConeCost::Create(a0, cone, 1.5),
                                         {pose.data()});
  }
  // The pose itself at the pole, outside the cone of a tilted start.
  std::array<double, 5> at_pole = {0.0, 0.3, 1, 2, 3};
  testing::ExpectJacobiansMatchNumeric(
      AxisConeCost::Create(AnglesToAxis(0.5, 0.0), cone, 1.0),
      {at_pole.data()});
}

}  // namespace
}  // namespace tpopt
