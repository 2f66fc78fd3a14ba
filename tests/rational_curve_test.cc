#include "model/geometry/rational_curve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tpopt {
namespace {

// A quarter circle of radius 10 as a rational quadratic (Piegl & Tiller,
// ex. 7.1): control points (10,0), (10,10), (0,10), weights 1, 1/sqrt2, 1.
RationalCurve QuarterCircle() {
  RationalCurve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.control_points = {{10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  c.weights = {1, std::sqrt(0.5), 1};
  return c;
}

TEST(RationalCurveTest, RationalQuadraticIsACircleAndChordsKeepTheTolerance) {
  const RationalCurve c = QuarterCircle();
  for (double t = 0; t <= 1.0; t += 0.05) {
    EXPECT_NEAR(RationalCurvePoint(c, t).norm(), 10.0, 1e-12) << t;
  }
  std::vector<Eigen::Vector3d> points;
  ASSERT_TRUE(RationalCurvePoints(c, 0.01, "c", &points).ok());
  EXPECT_NEAR((points.back() - Eigen::Vector3d(0, 10, 0)).norm(), 0.0, 1e-12);
  // The true sag of each chord of a circle: r (1 - cos(half angle)).
  Eigen::Vector3d prev(10, 0, 0);
  double worst = 0.0;
  for (const Eigen::Vector3d& p : points) {
    EXPECT_NEAR(p.norm(), 10.0, 1e-9);
    const double angle = std::acos(std::clamp(prev.dot(p) / 100.0, -1.0, 1.0));
    worst = std::max(worst, 10.0 * (1 - std::cos(angle / 2)));
    prev = p;
  }
  EXPECT_LE(worst, 0.01);
  // Bisection at most halves a step too far: no chord needlessly short.
  EXPECT_GT(worst, 0.0025);
}

TEST(RationalCurveTest, NonRationalCubicMatchesBernsteinForm) {
  RationalCurve c;
  c.degree = 3;
  c.knots = {5, 5, 5, 5, 7, 7, 7, 7};  // any range
  c.control_points = {{0, 0, 0}, {10, 20, 0}, {20, -20, 5}, {30, 0, 5}};
  for (double t : {0.0, 0.3, 0.5, 0.9, 1.0}) {
    const double s = 1 - t;
    const Eigen::Vector3d bernstein =
        s * s * s * c.control_points[0] + 3 * s * s * t * c.control_points[1] +
        3 * s * t * t * c.control_points[2] + t * t * t * c.control_points[3];
    EXPECT_NEAR((RationalCurvePoint(c, t) - bernstein).norm(), 0.0, 1e-12) << t;
  }
  std::vector<Eigen::Vector3d> points;
  ASSERT_TRUE(RationalCurvePoints(c, 0.005, "c", &points).ok());
  // Dense check of every chord against the curve.
  for (int i = 1; i <= 4000; ++i) {
    const Eigen::Vector3d q = RationalCurvePoint(c, i / 4000.0);
    // Its distance to the polyline bounds its distance to its own chord.
    double nearest = 1e9;
    Eigen::Vector3d a = c.control_points[0];
    for (const Eigen::Vector3d& b : points) {
      const Eigen::Vector3d ab = b - a;
      const double u = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (q - (a + u * ab)).norm());
      a = b;
    }
    EXPECT_LE(nearest, 0.005 + 1e-12);
  }
}

TEST(RationalCurveTest, RefusesBadCountsKnotsAndWeights) {
  RationalCurve c = QuarterCircle();
  std::vector<Eigen::Vector3d> points;
  c.weights = {1, -1, 1};
  Status s = RationalCurvePoints(c, 0.01, "p.cls:12", &points);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("p.cls:12: NURBS weight 2 (-1)"), std::string::npos) << s.message();
  c = QuarterCircle();
  c.knots = {0, 0, 1, 1, 1};
  EXPECT_FALSE(RationalCurvePoints(c, 0.01, "p.cls:12", &points).ok());
  c = QuarterCircle();
  c.weights = {1, 1};
  EXPECT_FALSE(RationalCurvePoints(c, 0.01, "p.cls:12", &points).ok());
  c = QuarterCircle();
  c.knots = {0, 0.5, 0, 1, 1, 1};
  EXPECT_FALSE(RationalCurvePoints(c, 0.01, "p.cls:12", &points).ok());
}

}  // namespace
}  // namespace tpopt
