// A whole pass and its metrics against what the geometry fixes exactly.
#include "solver/strip/strip_path.h"

#include <cmath>

#include <gtest/gtest.h>

#include "solver/strip/strip_path_metrics.h"
#include "tests/analytic_surfaces.h"

namespace tpopt {
namespace {

const TorusCutter kCutter{8.0, 2.0};

TEST(StripPathTest, FluctuationOfCentresOnACircleIsItsChordSagitta) {
  // Centres on a circle of radius 50 mm, 3 deg apart: every second
  // difference has length 2 * 50 * (1 - cos 3 deg).
  std::vector<StripPoint> points(12);
  for (size_t i = 0; i < points.size(); ++i) {
    const double angle = 3.0 * M_PI / 180.0 * i;
    points[i].tool_centre = 50.0 * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0);
    points[i].strip.s_minus = -1.0 - 0.1 * i;
    points[i].strip.s_plus = 1.0;
  }
  const StripPathMetrics m = MeasureStripPath(points);
  const double expected = 2 * 50 * (1 - std::cos(3.0 * M_PI / 180.0));
  EXPECT_NEAR(m.centre_fluctuation_max_mm, expected, 1e-12);
  EXPECT_NEAR(m.centre_fluctuation_rms_mm, expected, 1e-12);
  EXPECT_NEAR(m.cc_second_difference_max_mm, 0.0, 1e-12);
  EXPECT_NEAR(m.min_width_mm, 2.0, 1e-12);
  EXPECT_NEAR(m.max_width_mm, 2.0 + 1.1, 1e-12);
  EXPECT_NEAR(m.max_strip_mid_offset_mm, 0.55, 1e-12);
}

TEST(StripPathTest, SturzOnAConvexCylinderAroundItsAxis) {
  // A pass around a convex cylinder of radius 30 mm (feed around, cross
  // direction along the axis, where the section is straight): each pose is
  // the first one turned about the axis, so the tool centres lie on one
  // circle about it, and every strip has the plane's closed-form width.
  const testing::CylinderSurface cylinder(30, 1.0, 80, true);
  StripPathOptions options;
  options.method = PostureMethod::kSturz;
  options.poses = 9;
  options.samples_per_side = 200;
  options.posture.tolerance_mm = 0.002;
  std::vector<StripPoint> points;
  ASSERT_TRUE(PlanStripPath(cylinder, kCutter, options, &points).ok());
  const double width = QuadraticStripWidth(
      0.002, EffectiveRadiusAtLead(kCutter, options.posture.sturz_lead_rad), 0.0);
  const double radius = Eigen::Vector2d(points[0].tool_centre.x(), points[0].tool_centre.y()).norm();
  for (const StripPoint& p : points) {
    EXPECT_NEAR(p.strip.width(), width, 0.01 * width);
    EXPECT_NEAR(Eigen::Vector2d(p.tool_centre.x(), p.tool_centre.y()).norm(), radius, 1e-9);
    EXPECT_NEAR(p.tool_centre.z(), points[0].tool_centre.z(), 1e-9);
  }
  // Equal angular steps of 0.9 rad / 8 on that circle.
  const StripPathMetrics m = MeasureStripPath(points);
  EXPECT_NEAR(m.centre_fluctuation_max_mm, 2 * radius * (1 - std::cos(0.9 / 8)), 1e-9);
}

}  // namespace
}  // namespace tpopt
