// The seed's pencil example end to end in the library: the fit passes
// through every CL point and cuts the chord error of straight moves by at
// least 10x; a ball larger than a trough's radius is reported as folding.
#include "solver/fit/pencil_fit.h"

#include <gtest/gtest.h>

#include "model/io/pencil_job.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::SourcePath;

TEST(PencilFitTest, TheSeedsExampleInterpolatesEveryPointAndBeatsStraightMovesTenfold) {
  PencilOptions options;  // 3000 mm/min, 8 ms, 3 mm ball
  PencilJob job;
  ASSERT_TRUE(LoadPencilJob(SourcePath("data/pencil/surface_120x120x55.json"),
                            SourcePath("data/pencil/flower_guides.json"), options.ball_radius_mm,
                            &job)
                  .ok());
  const PencilGeometry& geometry = job.geometry;
  const std::vector<BSplineCurve>& guides = job.guides;
  std::vector<PencilRun> runs;
  ASSERT_TRUE(GeneratePencilRuns(geometry, guides, options, &runs).ok());
  PencilFitResult fit;
  ASSERT_TRUE(FitPencilRuns(geometry, guides, runs, options.ball_radius_mm, CurveOutputOptions(),
                            true, &fit)
                  .ok());
  EXPECT_EQ(fit.folded_points, 0u);
  EXPECT_GE(fit.errors.max_chord_error_mm, 10 * fit.errors.max_fit_error_mm)
      << fit.errors.max_chord_error_mm << " vs " << fit.errors.max_fit_error_mm;
  // Every span starts and ends on a CL point's tip.
  const Eigen::Vector3d to_tip = -options.ball_radius_mm * geometry.tool_axis();
  size_t span = 0;
  for (const PencilRun& run : runs) {
    for (size_t i = 0; i + 1 < run.points.size(); ++i, ++span) {
      ASSERT_LT(span, fit.spans.size());
      EXPECT_LT((fit.spans[span].bezier[0] - (run.points[i].cl + to_tip)).norm(), 1e-9);
      EXPECT_LT((fit.spans[span].bezier[3] - (run.points[i + 1].cl + to_tip)).norm(), 1e-9);
      EXPECT_EQ(fit.path.poses[fit.spans[span].after_pose].p_w_tip, fit.spans[span].bezier[0]);
    }
  }
  EXPECT_EQ(span, fit.spans.size());
  // Runs are joined by rapids: retract, approach, then feed down.
  size_t rapids = 0;
  for (const ToolPose& p : fit.path.poses) rapids += p.rapid;
  EXPECT_EQ(rapids, 2 * runs.size() - 1);
}

// A trough z = x^2 / 2 (curvature 1 / mm at its bottom), as a quadratic
// Bezier in x and linear in y.
BSplineSurface Trough() {
  std::vector<std::vector<Eigen::Vector3d>> net(3, std::vector<Eigen::Vector3d>(2));
  const double x[3] = {-5, 0, 5}, z[3] = {12.5, -12.5, 12.5};  // z(0) = 0, z(+-5) = 12.5
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 2; ++j) net[i][j] = {x[i], j == 0 ? -5.0 : 5.0, z[i]};
  }
  BSplineSurface s;
  EXPECT_TRUE(BSplineSurface::Create(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, net, "trough", &s).ok());
  return s;
}

TEST(PencilFitTest, ABallWiderThanTheTroughFolds) {
  const BSplineSurface trough = Trough();
  BSplineCurve across;
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{-2, 0, 0}, {2, 0, 0}}, "across", &across).ok());
  for (double radius : {0.5, 3.0}) {
    PencilOptions options;
    options.ball_radius_mm = radius;
    PencilGeometry geometry;
    ASSERT_TRUE(PencilGeometry::Create(trough, GuidePlacement(), radius, &geometry).ok());
    std::vector<PencilRun> runs;
    ASSERT_TRUE(GeneratePencilRuns(geometry, {across}, options, &runs).ok());
    PencilFitResult fit;
    ASSERT_TRUE(FitPencilRuns(geometry, {across}, runs, radius, CurveOutputOptions(), false, &fit).ok());
    // The centre runs backwards where the radius of curvature (1 + x^2)^1.5
    // is below the ball's: |x| < a = sqrt(radius^(2/3) - 1), an arc of
    // a sqrt(1 + a^2) + asinh(a) mm, covered at one point per step.
    if (radius < 1.0) {
      EXPECT_EQ(fit.folded_points, 0u);
    } else {
      const double a = std::sqrt(std::pow(radius, 2.0 / 3.0) - 1.0);
      const double arc = a * std::sqrt(1 + a * a) + std::asinh(a);
      EXPECT_NEAR(fit.folded_points * options.StepMm(), arc, options.StepMm());
    }
    EXPECT_TRUE(fit.spans.empty());
  }
}

}  // namespace
}  // namespace tpopt
