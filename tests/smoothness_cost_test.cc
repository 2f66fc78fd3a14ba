#include "solver/smooth/cost/smoothness_cost.h"

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

// Poses whose A, C and x follow polynomials of the arc length s.
std::array<double, 5> PoseAt(double s) {
  return {0.01 * s * s, 0.002 * s * s * s, 3 * s * s, 1.0, -2.0};
}

TEST(SmoothnessCostTest, SecondDerivativeOfAQuadraticIsExactOnUnevenSteps) {
  const std::array<double, 3> s = {0.0, 0.7, 2.0};
  std::array<std::array<double, 5>, 3> p = {PoseAt(s[0]), PoseAt(s[1]), PoseAt(s[2])};
  // w = L / h makes the scale 1, so residuals are the raw derivatives.
  const double length = 10.0, h = 1.0;
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessCost<2>::Create(s, length, length / h, length / h));
  double r[5];
  const double* params[] = {p[0].data(), p[1].data(), p[2].data()};
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[kPoseA], 0.02, 1e-12);  // d2/ds2 of 0.01 s^2
  EXPECT_NEAR(r[kPoseTip], 6.0, 1e-12);
  EXPECT_NEAR(r[kPoseTip + 1], 0.0, 1e-12);
}

TEST(SmoothnessCostTest, ThirdDerivativeOfACubicIsExact) {
  const std::array<double, 4> s = {0.0, 0.5, 1.75, 2.5};
  std::array<std::array<double, 5>, 4> p = {PoseAt(s[0]), PoseAt(s[1]), PoseAt(s[2]),
                                             PoseAt(s[3])};
  const double length = 5.0, h = 2.5 / 3;
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessCost<3>::Create(s, length, length / h, length / h));
  double r[5];
  const double* params[] = {p[0].data(), p[1].data(), p[2].data(), p[3].data()};
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[kPoseC], 0.012, 1e-12);  // 6 * 0.002
  EXPECT_NEAR(r[kPoseA], 0.0, 1e-12);
}

TEST(SmoothnessCostTest, DifferentiatesTheDepartureFromAReference) {
  // Angles = reference + a quadratic departure: only the departure's d2
  // remains (A: 0.01 s^2 -> 0.02; C: its cubic reference cancels exactly),
  // and the tip is untouched.
  const std::array<double, 3> s = {0.0, 0.7, 2.0};
  std::array<std::array<double, 5>, 3> p;
  SmoothnessCost<2>::Reference reference;
  for (int j = 0; j < 3; ++j) {
    reference[j] = {0.3 * s[j] * s[j] + 1.0, 0.002 * s[j] * s[j] * s[j]};
    p[j] = PoseAt(s[j]);
    p[j][kPoseA] += reference[j][0];
  }
  const double length = 10.0, h = 1.0;
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessCost<2>::Create(s, length, length / h, length / h, reference));
  double r[5];
  const double* params[] = {p[0].data(), p[1].data(), p[2].data()};
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[kPoseA], 0.02, 1e-12);
  EXPECT_NEAR(r[kPoseC], 0.0, 1e-12);
  EXPECT_NEAR(r[kPoseTip], 6.0, 1e-12);
}

TEST(SmoothnessCostTest, AAndCWeighApart) {
  // A and C on the same quadratic (d2 = 2): each residual scales with the
  // square root of its own weight (h = 1, L = 10: sqrt(w / 10) * 2).
  const std::array<double, 3> s = {0.0, 1.0, 2.0};
  std::array<std::array<double, 5>, 3> p;
  for (int j = 0; j < 3; ++j) {
    p[j] = PoseAt(s[j]);
    p[j][kPoseA] = p[j][kPoseC] = s[j] * s[j];
  }
  std::unique_ptr<ceres::CostFunction> cost(
      SmoothnessCost<2>::Create(s, 10.0, std::array<double, 2>{1000.0, 10.0}, 0.0));
  double r[5];
  const double* params[] = {p[0].data(), p[1].data(), p[2].data()};
  ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[kPoseA], 20.0, 1e-9);
  EXPECT_NEAR(r[kPoseC], 2.0, 1e-9);
}

TEST(SmoothnessCostTest, JacobiansMatchNumericDifferences) {
  std::array<std::array<double, 5>, 4> p = {PoseAt(0.1), PoseAt(1.0), PoseAt(2.2), PoseAt(3.0)};
  testing::ExpectJacobiansMatchNumeric(
      SmoothnessCost<2>::Create({0.1, 1.0, 2.2}, 10, 5, 0.5),
      {p[0].data(), p[1].data(), p[2].data()});
  testing::ExpectJacobiansMatchNumeric(
      SmoothnessCost<3>::Create({0.1, 1.0, 2.2, 3.0}, 10, 5, 0.5),
      {p[0].data(), p[1].data(), p[2].data(), p[3].data()});
}

}  // namespace
}  // namespace tpopt
