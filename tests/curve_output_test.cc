// Curve output of a tool path: runs split at rapids and corners, every
// input pose kept, resampled points on the spans, spans on a circle close
// to it, and a file that reads back.
#include "solver/fit/curve_output.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

ToolPose Pose(const Eigen::Vector3d& tip, bool rapid = false) {
  ToolPose p;
  p.p_w_tip = tip;
  p.a_w = Eigen::Vector3d(0, 0.6, 0.8);
  p.feed_mm_per_min = 1200;
  p.rapid = rapid;
  return p;
}

// 12 points on a circle of radius 10 (1 mm chords), a 90 degree corner, a
// straight leg of 3 points, then a rapid to a short run of 2 points.
ToolPath Sample() {
  ToolPath path;
  for (int k = 0; k < 12; ++k) {
    const double a = 0.1 * k;
    path.poses.push_back(Pose({10 * std::cos(a), 10 * std::sin(a), 0}));
  }
  const Eigen::Vector3d corner = path.poses.back().p_w_tip;
  const Eigen::Vector3d radial(std::cos(1.1), std::sin(1.1), 0);
  for (int k = 1; k <= 3; ++k) path.poses.push_back(Pose(corner + k * radial));
  path.poses.push_back(Pose({0, 0, 50}, true));
  path.poses.push_back(Pose({1, 0, 50}));
  return path;
}

TEST(CurveOutputTest, FitsRunsKeepsEveryPoseAndResamplesOnTheSpans) {
  const ToolPath in = Sample();
  CurveOutputOptions options;
  options.sample_step_mm = 0.25;
  ToolPath out;
  std::vector<AptCurveSpan> spans;
  ASSERT_TRUE(FitToolPathCurves(in, options, &out, &spans).ok());
  // The circle (11 spans) and the leg from its corner on (3 spans) are
  // runs of 4 or more; the run after the rapid is not. 1 mm chords make
  // 4 pieces each.
  ASSERT_EQ(spans.size(), 14u);
  EXPECT_EQ(out.poses.size(), in.poses.size() + 14 * 3);
  // Every input pose appears, in order, unchanged.
  size_t j = 0;
  for (const ToolPose& p : out.poses) {
    if (j < in.poses.size() && p.p_w_tip == in.poses[j].p_w_tip && p.rapid == in.poses[j].rapid) ++j;
  }
  EXPECT_EQ(j, in.poses.size());
  const Eigen::Vector3d radial(std::cos(1.1), std::sin(1.1), 0);
  for (size_t s = 11; s < 14; ++s) {
    for (const Eigen::Vector3d& b : spans[s].bezier) {
      const Eigen::Vector3d off = b - in.poses[11].p_w_tip;
      EXPECT_LT((off - off.dot(radial) * radial).norm(), 1e-12);  // the leg stays straight
    }
  }
  spans.resize(11);
  for (const AptCurveSpan& span : spans) {
    EXPECT_EQ(out.poses[span.after_pose].p_w_tip, span.bezier[0]);
    // Resampled points lie on the circle to within the fit's error, far
    // below the 1 mm chords' sagitta of 12.5 um.
    for (size_t k = span.after_pose + 1; k <= span.after_pose + 4; ++k) {
      const Eigen::Vector3d& q = out.poses[k].p_w_tip;
      EXPECT_LT(std::abs(std::hypot(q.x(), q.y()) - 10.0), 1e-4) << k;
      EXPECT_NEAR(out.poses[k].a_w.norm(), 1.0, 1e-12);
      EXPECT_FALSE(out.poses[k].rapid);
    }
  }
}

TEST(CurveOutputTest, WrittenFileReadsBackWithoutWarnings) {
  testing::TempDir dir;
  ToolPath out;
  std::vector<AptCurveSpan> spans;
  ASSERT_TRUE(FitToolPathCurves(Sample(), CurveOutputOptions(), &out, &spans).ok());
  const std::string file = dir.File("c.cls");
  ASSERT_TRUE(WriteApt(file, out, spans).ok());
  ToolPath back;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadApt(file, &back, &warnings).ok());
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(back.poses.size(), out.poses.size());
  for (size_t i = 0; i < out.poses.size(); ++i) {
    EXPECT_LT((back.poses[i].p_w_tip - out.poses[i].p_w_tip).norm(), 1e-6) << i;
  }
}

TEST(CurveOutputTest, BadOptionsAreRefused) {
  CurveOutputOptions options;
  options.sample_step_mm = 0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("step"), std::string::npos);
  ToolPath out;
  std::vector<AptCurveSpan> spans;
  EXPECT_FALSE(FitToolPathCurves(Sample(), options, &out, &spans).ok());
}

}  // namespace
}  // namespace tpopt
