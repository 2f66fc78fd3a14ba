#include "model/geometry/ruled_surface.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

BSplineCurve Line(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  BSplineCurve c;
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {a, b}, "line", &c).ok());
  return c;
}

// The shared hyperbolic paraboloid (data/surfaces/hypar.json).
RuledSurface Hypar(CutterSide side) {
  return RuledSurface("hypar", Line({0, 0, 0}, {60, 0, 0}), Line({0, 6, 30}, {60, -6, 30}), side);
}

// Gaussian curvature from the Weingarten map, with finite differences of the
// unit normal: K = (N_u x N_v) . N / ((r_u x r_v) . N). Independent of the
// second-fundamental-form expression the implementation uses.
double CurvatureFromNormalField(const RuledSurface& s, double u, double v) {
  const double h = 1e-6;
  const Eigen::Vector3d nu = (s.Normal(u + h, v) - s.Normal(u - h, v)) / (2 * h);
  const Eigen::Vector3d nv = (s.Normal(u, v + h) - s.Normal(u, v - h)) / (2 * h);
  const Eigen::Vector3d n = s.Normal(u, v);
  return nu.cross(nv).dot(n) / s.Du(u, v).cross(s.Dv(u)).dot(n);
}

TEST(RuledSurfaceTest, HyparPointsNormalsAndCurvature) {
  const RuledSurface s = Hypar(CutterSide::kPositive);
  EXPECT_LT((s.Point(0.5, 0.5) - Eigen::Vector3d(30, 0, 15)).norm(), 1e-12);
  // r_u = (60, -12 v, 0), r_v = (0, 6 - 12 u, 30): n = (-360 v, -1800, 360 - 720 u).
  const double u = 0.3, v = 0.8;
  const Eigen::Vector3d n_expected = Eigen::Vector3d(-360 * v, -1800, 360 - 720 * u).normalized();
  EXPECT_LT((s.Normal(u, v) - n_expected).norm(), 1e-12);
  EXPECT_LT((Hypar(CutterSide::kNegative).Normal(u, v) + n_expected).norm(), 1e-12);
  for (double uu : {0.1, 0.5, 0.9}) {
    for (double vv : {0.1, 0.5, 0.9}) {
      const double k = s.GaussianCurvature(uu, vv);
      EXPECT_LT(k, 0.0);
      EXPECT_NEAR(k, CurvatureFromNormalField(s, uu, vv), 1e-6 * std::abs(k)) << uu << " " << vv;
    }
  }
}

TEST(RuledSurfaceTest, CylinderPatchIsDevelopable) {
  // Two copies of a quadratic arc, one above the other: a general cylinder.
  BSplineCurve c1, c2;
  ASSERT_TRUE(BSplineCurve::Create(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {10, 10, 0}, {20, 0, 0}},
                                   "c1", &c1)
                  .ok());
  ASSERT_TRUE(BSplineCurve::Create(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 20}, {10, 10, 20}, {20, 0, 20}},
                                   "c2", &c2)
                  .ok());
  const RuledSurface s("cyl", c1, c2, CutterSide::kPositive);
  for (double u : {0.2, 0.5, 0.7}) {
    EXPECT_NEAR(s.GaussianCurvature(u, 0.4), 0.0, 1e-15);
    // The normal is the same all along a ruling of a developable surface.
    EXPECT_LT((s.Normal(u, 0) - s.Normal(u, 1)).norm(), 1e-12);
  }
  // Rail curvature radius of the parabola-like arc at its apex: |C'|^3/|C' x C''|
  // with C' = (20, 0, 0) and C'' = (0, -40, 0): 8000 / 800 = 10 mm.
  EXPECT_NEAR(s.RailCurvatureRadius(1, 0.5), 10.0, 1e-12);
}

}  // namespace
}  // namespace tpopt
