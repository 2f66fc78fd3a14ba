// Projection along a direction onto surfaces whose intersections are known.
#include "model/geometry/surface_projection.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

// z = x^2 y over [0, 40] x [0, 30] (see bspline_surface_test.cc).
BSplineSurface Patch() {
  const double u2[4] = {0, 0, 1.0 / 3, 1}, lin[4] = {0, 1.0 / 3, 2.0 / 3, 1};
  std::vector<std::vector<Eigen::Vector3d>> net(4, std::vector<Eigen::Vector3d>(4));
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) net[i][j] = {40 * lin[i], 30 * lin[j], 20 * u2[i] * lin[j]};
  }
  BSplineSurface s;
  EXPECT_TRUE(BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1},
                                     net, "patch", &s)
                  .ok());
  return s;
}

TEST(SurfaceProjectionTest, VerticalLinesHitTheGraphAtTheirXY) {
  const BSplineSurface s = Patch();
  const Eigen::Vector3d down(0, 0, -1);
  Eigen::Vector2d guess(0.9, 0.1);  // far from the answer: Newton must travel
  for (double x : {1.0, 13.0, 39.0}) {
    for (double y : {2.0, 29.0}) {
      SurfaceHit hit;
      ASSERT_TRUE(ProjectAlongDirection(s, {x, y, 50}, down, &guess, &hit).ok());
      const double u = x / 40, v = y / 30;
      EXPECT_NEAR(hit.u, u, 1e-10);
      EXPECT_NEAR(hit.v, v, 1e-10);
      EXPECT_NEAR(hit.point.z(), 20 * u * u * v, 1e-9);
      EXPECT_NEAR(hit.distance_mm, 50 - 20 * u * u * v, 1e-9);
    }
  }
}

TEST(SurfaceProjectionTest, ObliqueDirectionAndNoGuessUseTheGridFallback) {
  const BSplineSurface s = Patch();
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 1, -4).normalized();
  SurfaceHit hit;
  ASSERT_TRUE(ProjectAlongDirection(s, {10, 10, 30}, dir, nullptr, &hit).ok());
  // The hit lies on the line and on the surface.
  const Eigen::Vector3d on_line = Eigen::Vector3d(10, 10, 30) + hit.distance_mm * dir;
  EXPECT_LT((on_line - hit.point).norm(), 1e-8);
  EXPECT_NEAR(hit.point.z(), 20 * std::pow(hit.point.x() / 40, 2) * hit.point.y() / 30, 1e-9);
}

TEST(SurfaceProjectionTest, ALineBesideTheSurfaceIsAnError) {
  const BSplineSurface s = Patch();
  SurfaceHit hit;
  const Status st = ProjectAlongDirection(s, {60, 10, 30}, {0, 0, -1}, nullptr, &hit);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("misses the surface"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace tpopt
