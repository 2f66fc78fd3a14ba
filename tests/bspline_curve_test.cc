#include "model/geometry/bspline_curve.h"

#include <random>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

// Cubic Bezier as a clamped B-spline on the knot range [2, 5], which must be
// mapped to [0, 1].
BSplineCurve Bezier(const std::vector<Eigen::Vector3d>& p) {
  BSplineCurve c;
  EXPECT_TRUE(BSplineCurve::Create(3, {2, 2, 2, 2, 5, 5, 5, 5}, p, "bezier", &c).ok());
  return c;
}

TEST(BSplineCurveTest, CubicBezierMatchesBernsteinFormAndItsDerivatives) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 0, 2}};
  const BSplineCurve c = Bezier(p);
  for (double u : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const double w = 1 - u;
    const Eigen::Vector3d point =
        w * w * w * p[0] + 3 * w * w * u * p[1] + 3 * w * u * u * p[2] + u * u * u * p[3];
    const Eigen::Vector3d d1 =
        3 * (w * w * (p[1] - p[0]) + 2 * w * u * (p[2] - p[1]) + u * u * (p[3] - p[2]));
    const Eigen::Vector3d d2 = 6 * (w * (p[2] - 2 * p[1] + p[0]) + u * (p[3] - 2 * p[2] + p[1]));
    const Eigen::Vector3d d3 = 6 * (p[3] - 3 * p[2] + 3 * p[1] - p[0]);
    const auto d = c.Evaluate(u, 3);
    EXPECT_LT((d[0] - point).norm(), 1e-12) << u;
    EXPECT_LT((d[1] - d1).norm(), 1e-11) << u;
    EXPECT_LT((d[2] - d2).norm(), 1e-10) << u;
    EXPECT_LT((d[3] - d3).norm(), 1e-10) << u;
  }
}

TEST(BSplineCurveTest, DerivativesMatchFiniteDifferencesOnManyKnots) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-10, 10);
  std::vector<Eigen::Vector3d> p(9);
  for (auto& q : p) q = {coord(rng), coord(rng), coord(rng)};
  const std::vector<double> knots = {0, 0, 0, 0, 0.1, 0.3, 0.3, 0.6, 0.8, 1, 1, 1, 1};
  BSplineCurve c;
  ASSERT_TRUE(BSplineCurve::Create(3, knots, p, "c", &c).ok());
  const double h = 1e-5;
  for (double u = 0.02; u < 0.98; u += 0.0371) {
    const auto d = c.Evaluate(u, 3);
    const auto dp = c.Evaluate(u + h, 3), dm = c.Evaluate(u - h, 3);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d fd = (dp[k] - dm[k]) / (2 * h);
      EXPECT_LT((fd - d[k + 1]).norm(), 1e-4 * (1 + d[k + 1].norm())) << "u " << u << " k " << k;
    }
  }
  // Clamped: the ends interpolate the end control points.
  EXPECT_LT((c.Point(0) - p.front()).norm(), 1e-12);
  EXPECT_LT((c.Point(1) - p.back()).norm(), 1e-12);
}

TEST(BSplineCurveTest, QuadraticArcCurvatureRadiusMatchesParabola) {
  // y = x^2 / 2 as a quadratic Bezier: radius of curvature at the vertex is 1.
  BSplineCurve c;
  ASSERT_TRUE(BSplineCurve::Create(2, {0, 0, 0, 1, 1, 1},
                                   {{-1, 0.5, 0}, {0, -0.5, 0}, {1, 0.5, 0}}, "parabola", &c)
                  .ok());
  EXPECT_NEAR(c.CurvatureRadius(0.5), 1.0, 1e-12);
  // At x = 1: (1 + x^2)^{3/2} = 2^{3/2}.
  EXPECT_NEAR(c.CurvatureRadius(1.0), std::pow(2.0, 1.5), 1e-9);
  BSplineCurve line;
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 1, 1}}, "line", &line).ok());
  EXPECT_TRUE(std::isinf(line.CurvatureRadius(0.3)));
}

TEST(BSplineCurveTest, RejectsInconsistentInputNamingIt) {
  BSplineCurve c;
  const std::vector<Eigen::Vector3d> p4 = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  Status s = BSplineCurve::Create(3, {0, 0, 0, 1, 1, 1, 1}, p4, "rails[0]", &c);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("rails[0]"), std::string::npos);
  EXPECT_NE(s.message().find("7 knots"), std::string::npos) << s.message();
  s = BSplineCurve::Create(1, {0, 0, 0.7, 0.5, 1, 1}, p4, "rails[1]", &c);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("decrease at index 3"), std::string::npos) << s.message();
  s = BSplineCurve::Create(3, {0, 0, 0, 0.2, 1, 1, 1, 1}, p4, "r", &c);
  EXPECT_NE(s.message().find("not clamped"), std::string::npos) << s.message();
  s = BSplineCurve::Create(3, {1, 1, 1, 1, 1, 1, 1, 1}, p4, "r", &c);
  EXPECT_NE(s.message().find("empty"), std::string::npos) << s.message();
  auto bad = p4;
  bad[2].x() = std::nan("");
  s = BSplineCurve::Create(3, {0, 0, 0, 0, 1, 1, 1, 1}, bad, "r", &c);
  EXPECT_NE(s.message().find("control point 2"), std::string::npos) << s.message();
  s = BSplineCurve::Create(0, {0, 1}, {{0, 0, 0}}, "r", &c);
  EXPECT_NE(s.message().find("degree 0"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace tpopt
