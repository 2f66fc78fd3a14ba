#include "model/geometry/circular_arc.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace tpopt {
namespace {

// The largest distance of the arc from the polyline start, points...:
// sampled densely on the true arc (closed form), each sample's distance to
// the nearest chord.
double WorstSag(const CircularArc& arc, const Eigen::Vector3d& start,
                const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> poly = {start};
  poly.insert(poly.end(), points.begin(), points.end());
  double worst = 0.0;
  for (size_t k = 1; k < poly.size(); ++k) {
    const Eigen::Vector3d a = poly[k - 1] - arc.center, b = poly[k] - arc.center;
    for (int s = 1; s < 20; ++s) {
      // The arc point between two chord ends at the same radius (planar arc
      // here): slerp of their directions.
      const double t = s / 20.0;
      const double angle = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
      const Eigen::Vector3d q =
          arc.radius_mm *
          (std::sin((1 - t) * angle) * a.normalized() + std::sin(t * angle) * b.normalized()) /
          std::sin(angle);
      const Eigen::Vector3d ab = b - a;
      const double u = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (q - (a + u * ab)).norm());
    }
  }
  return worst;
}

TEST(CircularArcTest, QuarterArcCounterClockwiseAboutPlusZWithinTolerance) {
  CircularArc arc{Eigen::Vector3d(10, 20, 5), Eigen::Vector3d::UnitZ(), 15.0};
  const Eigen::Vector3d start(25, 20, 5), end(10, 35, 5);
  std::vector<Eigen::Vector3d> points;
  ASSERT_TRUE(ArcPoints(arc, start, end, 0.01, 1e-6, "a", &points).ok());
  // Steps: 2 acos(1 - 0.01/15) = 0.07303 rad, so ceil((pi/2)/0.07303) = 22.
  EXPECT_EQ(points.size(), 22u);
  EXPECT_EQ(points.back(), end);
  for (const Eigen::Vector3d& p : points) {
    EXPECT_NEAR((p - arc.center).norm(), 15.0, 1e-9);
    // Counter-clockwise from +X to +Y: every point in the first quadrant.
    EXPECT_GE(p.x() - 10, -1e-9);
    EXPECT_GE(p.y() - 20, -1e-9);
    EXPECT_NEAR(p.z(), 5, 1e-12);
  }
  const double sag = WorstSag(arc, start, points);
  EXPECT_LE(sag, 0.01);
  EXPECT_GT(sag, 0.005);  // not needlessly dense
}

TEST(CircularArcTest, MinusAxisTurnsClockwiseTheLongWay) {
  // The same end points about -Z: clockwise from +X to +Y, three quarters.
  CircularArc arc{Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitZ(), 10.0};
  std::vector<Eigen::Vector3d> points;
  ASSERT_TRUE(
      ArcPoints(arc, Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0), 0.1, 1e-6, "a", &points)
          .ok());
  bool passed_minus_y = false;
  for (const Eigen::Vector3d& p : points) passed_minus_y |= p.y() < -9.9;
  EXPECT_TRUE(passed_minus_y);
  EXPECT_LE(WorstSag(arc, Eigen::Vector3d(10, 0, 0), points), 0.1);
}

TEST(CircularArcTest, FullCircleAndHelix) {
  CircularArc arc{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 5.0};
  const Eigen::Vector3d start(0, 5, 0);
  std::vector<Eigen::Vector3d> points;
  ASSERT_TRUE(ArcPoints(arc, start, start, 0.05, 1e-6, "a", &points).ok());
  // A full turn: the angle sum of the chords is 2 pi.
  double turned = 0.0;
  Eigen::Vector3d prev = start;
  for (const Eigen::Vector3d& p : points) {
    turned += std::acos(std::clamp(prev.normalized().dot(p.normalized()), -1.0, 1.0));
    prev = p;
  }
  EXPECT_NEAR(turned, 2 * M_PI, 1e-9);
  // Helix: from height 0 to 3 along the axis, linearly in the angle.
  const Eigen::Vector3d end(3, -5, 0);  // half a turn about +X, 3 mm along it
  ASSERT_TRUE(ArcPoints(arc, start, end, 0.05, 1e-6, "a", &points).ok());
  for (size_t k = 0; k < points.size(); ++k) {
    const double angle = std::atan2(points[k].z(), points[k].y());
    const double expected_x = 3.0 * (angle < 0 ? angle + 2 * M_PI : angle) / M_PI;
    EXPECT_NEAR(points[k].x(), k + 1 == points.size() ? 3.0 : expected_x, 1e-9);
  }
}

TEST(CircularArcTest, RefusesEndsOffTheCircleAndBadArguments) {
  CircularArc arc{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 10.0};
  std::vector<Eigen::Vector3d> points;
  Status s = ArcPoints(arc, Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10.5, 0), 0.01, 1e-3,
                       "p.cls:7", &points);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("p.cls:7: the arc's end point lies 10.5 mm"), std::string::npos)
      << s.message();
  arc.radius_mm = 0.0;
  EXPECT_FALSE(
      ArcPoints(arc, Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0), 0.01, 1e-3, "a", &points)
          .ok());
  arc = CircularArc{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 10.0};
  EXPECT_FALSE(
      ArcPoints(arc, Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0), 0.01, 1e-3, "a", &points)
          .ok());
}

}  // namespace
}  // namespace tpopt
