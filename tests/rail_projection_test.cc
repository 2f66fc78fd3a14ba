#include "model/path/rail_projection.h"

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

// Quarter circle of radius 10 as a quadratic Bezier is not a circle, so use
// a cubic curve and check the defining property of the foot point instead.
BSplineCurve Curve() {
  BSplineCurve c;
  EXPECT_TRUE(BSplineCurve::Create(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                                   {{0, 0, 0}, {10, 5, 0}, {20, -5, 2}, {30, 0, 0}, {40, 8, 1}},
                                   "c", &c)
                  .ok());
  return c;
}

TEST(RailProjectionTest, FootPointIsOrthogonalAndRecoversKnownU) {
  const BSplineCurve c = Curve();
  for (double u : {0.05, 0.3, 0.5, 0.77, 0.95}) {
    const auto d = c.Evaluate(u, 1);
    // Offset 3 mm along a direction normal to the tangent.
    Eigen::Vector3d normal = d[1].cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d point = d[0] + 3.0 * normal;
    const double found = ProjectOntoCurve(c, point);
    EXPECT_NEAR(found, u, 1e-9);
  }
  // Beyond the ends the foot clamps to them.
  EXPECT_EQ(ProjectOntoCurve(c, {-10, 0, 0}), 0.0);
  EXPECT_EQ(ProjectOntoCurve(c, {60, 10, 1}), 1.0);
}

TEST(RailProjectionTest, PathProjectionIsMonotoneEvenWithLargeSteps) {
  const BSplineCurve c = Curve();
  ToolPath path;
  for (int i = 0; i <= 8; ++i) {
    ToolPose pose;
    pose.p_w_tip = c.Point(i / 8.0) + Eigen::Vector3d(0, 0, 2);
    path.poses.push_back(pose);
  }
  const std::vector<double> u = ProjectPathOntoRail(c, path);
  for (size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(u[i], i / 8.0, 0.02) << i;
  for (size_t i = 1; i < u.size(); ++i) EXPECT_GT(u[i], u[i - 1]);
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

TEST(RailProjectionTest, TipsNearTheCentreOfCurvatureKeepTheirRuling) {
  // Near u = 0.1 the bottom rail of the shared jcde2022 surface bends with a
  // radius of 4.13 mm, so the tips of a 4 mm cutter sit almost at its centre
  // of curvature, where the foot point is ill-conditioned (its slope is
  // |C'|^2 (1 - 4 / 4.13)); the search must still find the exact ruling. The
  // SPO path is generated at u = i / 299.
  RuledSurface surface;
  ASSERT_TRUE(
      ReadSurfaceJson(testing::SourcePath("data/surfaces/jcde2022.json"), &surface).ok());
  ASSERT_NEAR(surface.RailCurvatureRadius(0, 0.0973), 4.13, 0.01);
  FlankPathOptions options;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(surface, options, &path).ok());
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), path);
  for (size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(u[i], i / 299.0, 1e-6) << i;
}

// A flank path with its tip 2 mm below the floor along an axis that leans
// along the rail: the tip's foot lies off the contact ruling (past the
// rail's end at u = 1), the axis point level with the rail does not. The
// same path on the floor keeps its tip's foot.
TEST(RailProjectionTest, TipsBelowTheFloorProjectThroughTheAxis) {
  RuledSurface surface;
  ASSERT_TRUE(
      ReadSurfaceJson(testing::SourcePath("data/surfaces/impeller_blade.json"), &surface).ok());
  FlankPathOptions g;
  g.poses = 60;
  ToolPath on_floor;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &on_floor).ok());
  ToolPath below = on_floor;
  double worst_tip_foot = 0.0;
  for (size_t i = 0; i < below.poses.size(); ++i) {
    ToolPose& p = below.poses[i];
    p.p_w_tip -= 2.0 * p.a_w;
    const double u = i / 59.0;
    worst_tip_foot = std::max(worst_tip_foot,
                              std::abs(ProjectOntoCurve(surface.rail(0), p.p_w_tip) - u));
  }
  ASSERT_GT(worst_tip_foot, 1e-3);  // the tip's own foot is off its ruling
  const std::vector<double> u_below = ProjectPathOntoRail(surface.rail(0), below);
  const std::vector<double> u_floor = ProjectPathOntoRail(surface.rail(0), on_floor);
  for (size_t i = 0; i < below.poses.size(); ++i) {
    EXPECT_NEAR(u_below[i], i / 59.0, 1e-5) << i;  // 0.6 um along the rail
    EXPECT_NEAR(u_floor[i], i / 59.0, 1e-9) << i;
  }
  const std::vector<double> overhang = RunOverhangs(surface.rail(0), below, u_below);
  for (double h : overhang) EXPECT_NEAR(h, 2.0, 1e-4);
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

// A straight rail along x from 0 to 40 mm, the axis +z, tips 3 mm off it in
// y: lead-in poses 2 and 1 mm before x = 0, the end pose at x = 0, a pose
// 0.2 mm before it (within the noise level: the end ruling's own), poses
// inside, and a lead-out 1.5 mm past x = 40.
TEST(RailProjectionTest, PosesBeyondTheRailsEndsAreTheLeadInAndLeadOut) {
  BSplineCurve rail;
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {40, 0, 0}}, "r", &rail).ok());
  ToolPath path;
  for (double x : {-2.0, -1.0, -0.2, 0.0, 10.0, 20.0, 40.0, 41.5}) {
    ToolPose pose;
    pose.p_w_tip = {x, 3.0, 0.0};
    path.poses.push_back(pose);
  }
  const std::vector<double> u = ProjectPathOntoRail(rail, path);
  const std::vector<bool> beyond = PosesBeyondRailEnds(rail, path, u);
  const std::vector<bool> expected = {true, true, false, false, false, false, false, true};
  EXPECT_EQ(beyond, expected);
}

}  // namespace
}  // namespace tpopt
