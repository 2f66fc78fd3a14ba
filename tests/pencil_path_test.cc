// Pencil-path geometry: on a plane every quantity has a closed form; on the
// bundled free-form surface the analytic derivatives must match finite
// differences and the CL points must sit one ball radius off the surface.
#include "model/path/pencil_path.h"

#include <gtest/gtest.h>

#include "model/io/pencil_job.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::SourcePath;

// The plane z = 5 + 0.2 x - 0.1 y over [0, 100]^2 as a bicubic patch.
BSplineSurface TiltedPlane() {
  const double lin[4] = {0, 1.0 / 3, 2.0 / 3, 1};
  std::vector<std::vector<Eigen::Vector3d>> net(4, std::vector<Eigen::Vector3d>(4));
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x = 100 * lin[i], y = 100 * lin[j];
      net[i][j] = {x, y, 5 + 0.2 * x - 0.1 * y};
    }
  }
  BSplineSurface s;
  EXPECT_TRUE(BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1},
                                     net, "plane", &s)
                  .ok());
  return s;
}

BSplineCurve Segment(Eigen::Vector3d a, Eigen::Vector3d b) {
  BSplineCurve c;
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {a, b}, "segment", &c).ok());
  return c;
}

TEST(PencilPathTest, OnAPlaneCcIsTheGuideDroppedAlongTheNormal) {
  const BSplineSurface plane = TiltedPlane();
  GuidePlacement placement;
  placement.lift_mm = 12;
  placement.spin_deg = 35;
  PencilGeometry geometry;
  ASSERT_TRUE(PencilGeometry::Create(plane, placement, 1.5, &geometry).ok());
  const Eigen::Vector3d normal = Eigen::Vector3d(-0.2, 0.1, 1).normalized();
  EXPECT_LT((geometry.tool_axis() - normal).norm(), 1e-12);
  const BSplineCurve guide = Segment({-20, -5, 0}, {25, 10, 0});
  PencilOptions options;  // 3000 mm/min, 8 ms: 0.4 mm steps
  std::vector<PencilRun> runs;
  ASSERT_TRUE(GeneratePencilRuns(geometry, {guide}, options, &runs).ok());
  const auto& points = runs[0].points;
  const double length = std::hypot(45.0, 15.0);
  EXPECT_EQ(points.size(), static_cast<size_t>(std::ceil(length / 0.4 - 0.2)) + 1);
  for (size_t k = 0; k < points.size(); ++k) {
    const PencilPoint& p = points[k];
    const Eigen::Vector3d placed = geometry.Place(guide.Point(p.m));
    EXPECT_LT((p.cc - (placed - 12 * normal)).norm(), 1e-8) << k;
    EXPECT_LT((p.cl - (p.cc + 1.5 * normal)).norm(), 1e-12) << k;
    EXPECT_LT((p.dcl_dm - p.dcc_dm).norm(), 1e-9);  // the normal does not turn
    // The step rule is exact on a straight guide over a plane.
    if (k > 0 && k + 1 < points.size()) {
      EXPECT_NEAR((p.cc - points[k - 1].cc).norm(), 0.4, 1e-9);
    }
  }
  EXPECT_EQ(points.back().m, 1.0);
}

TEST(PencilPathTest, AnalyticDerivativesMatchFiniteDifferencesOnTheFreeFormSurface) {
  PencilJob job;
  ASSERT_TRUE(LoadPencilJob(SourcePath("data/pencil/surface_120x120x55.json"),
                            SourcePath("data/pencil/flower_guides.json"), 1.5, &job)
                  .ok());
  const PencilGeometry& geometry = job.geometry;
  const BSplineSurface& surface = job.surface;
  const std::vector<BSplineCurve>& guides = job.guides;
  for (double m : {0.1, 0.33, 0.72}) {
    PencilPoint p, plus, minus;
    Eigen::Vector2d uv;
    ASSERT_TRUE(geometry.At(guides[0], m, nullptr, &p).ok());
    uv = {p.u, p.v};
    ASSERT_TRUE(geometry.At(guides[0], m + 1e-5, &uv, &plus).ok());
    ASSERT_TRUE(geometry.At(guides[0], m - 1e-5, &uv, &minus).ok());
    const Eigen::Vector3d fd_cc = (plus.cc - minus.cc) / 2e-5, fd_cl = (plus.cl - minus.cl) / 2e-5;
    EXPECT_LT((p.dcc_dm - fd_cc).norm(), 1e-5 * fd_cc.norm()) << m;
    EXPECT_LT((p.dcl_dm - fd_cl).norm(), 1e-5 * fd_cl.norm()) << m;
    // The ball touches the surface at cc: cl is one radius along the normal.
    const Eigen::Vector3d n = surface.UnitNormal(p.u, p.v);
    EXPECT_NEAR(std::abs(n.dot(p.cl - p.cc)), 1.5, 1e-12);
    EXPECT_GT(p.normal.dot(geometry.tool_axis()), 0.0);
  }
}

TEST(PencilPathTest, AGuideRunningOffTheSurfaceFailsNamingCurveAndParameter) {
  const BSplineSurface plane = TiltedPlane();
  PencilGeometry geometry;
  ASSERT_TRUE(PencilGeometry::Create(plane, GuidePlacement(), 1.5, &geometry).ok());
  std::vector<PencilRun> runs;
  const Status s = GeneratePencilRuns(
      geometry, {Segment({0, 0, 0}, {5, 0, 0}), Segment({0, 0, 0}, {90, 0, 0})}, PencilOptions(),
      &runs);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("curve 1"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("guide parameter m = 0."), std::string::npos) << s.message();
  GuidePlacement bad;
  bad.anchor_u = 1.5;
  EXPECT_FALSE(PencilGeometry::Create(plane, bad, 1.5, &geometry).ok());
}

}  // namespace
}  // namespace tpopt
