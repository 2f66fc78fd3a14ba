// The global least-squares fit: exact on a cubic, within tolerance and
// far fewer control points than points on a helix, and bad input refused.
#include "solver/fit/bspline_least_squares.h"

#include <cmath>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

TEST(BSplineLeastSquaresTest, ACubicSampledUniformlyNeedsOnlyFourControlPoints) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k <= 40; ++k) {
    const double t = k / 40.0;
    points.push_back({10 * t, 3 * t * t - 2 * t, t * t * t + 0.5 * t});
  }
  LeastSquaresFitOptions options;
  options.parametrization = Parametrization::kUniform;
  options.tolerance_mm = 1e-9;
  LeastSquaresFit fit;
  ASSERT_TRUE(FitLeastSquares(points, options, &fit).ok());
  EXPECT_EQ(fit.curve.control_points().size(), 4u);
  EXPECT_LT(fit.max_error_mm, 1e-9);
  for (double t : {0.13, 0.5, 0.77}) {
    EXPECT_LT((fit.curve.Point(t) - Eigen::Vector3d(10 * t, 3 * t * t - 2 * t, t * t * t + 0.5 * t))
                  .norm(),
              1e-9);
  }
}

TEST(BSplineLeastSquaresTest, HelixWithinToleranceWithFewControlPoints) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k <= 300; ++k) {
    const double a = 0.02 * k;
    points.push_back({10 * std::cos(a), 10 * std::sin(a), 2 * a});
  }
  for (Parametrization kind : {Parametrization::kChordLength, Parametrization::kApproximateArc,
                               Parametrization::kCentripetal}) {
    LeastSquaresFitOptions options;
    options.parametrization = kind;
    options.tolerance_mm = 1e-3;
    LeastSquaresFit fit;
    ASSERT_TRUE(FitLeastSquares(points, options, &fit).ok());
    EXPECT_LE(fit.max_error_mm, 1e-3);
    EXPECT_LT(fit.curve.control_points().size(), points.size() / 4);
    EXPECT_EQ(fit.curve.Point(0), points.front());
    EXPECT_LT((fit.curve.Point(1) - points.back()).norm(), 1e-12);
  }
}

TEST(BSplineLeastSquaresTest, RefusesTooFewOrRepeatedPoints) {
  LeastSquaresFit fit;
  const std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  EXPECT_FALSE(FitLeastSquares(three, LeastSquaresFitOptions(), &fit).ok());
  const std::vector<Eigen::Vector3d> repeated = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  const Status s = FitLeastSquares(repeated, LeastSquaresFitOptions(), &fit);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("CL point 2"), std::string::npos) << s.message();
  LeastSquaresFitOptions zero;
  zero.tolerance_mm = 0;
  EXPECT_FALSE(FitLeastSquares(three, zero, &fit).ok());
}

}  // namespace
}  // namespace tpopt
