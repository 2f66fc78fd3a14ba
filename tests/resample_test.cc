#include "solver/smooth/resample.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

// A helix tip path with A and C varying smoothly with the angle t.
ToolPose HelixPose(double t) {
  ToolPose p;
  p.p_w_tip = Eigen::Vector3d(20 * std::cos(t), 20 * std::sin(t), 3 * t);
  p.a_w = AnglesToAxis(0.3 + 0.1 * std::sin(t), 0.5 * t);
  p.feed_mm_per_min = 800;
  return p;
}

TEST(ResampleTest, ReproducesASmoothPathAtTheRequestedStep) {
  ToolPath path;
  for (int i = 0; i <= 40; ++i) path.poses.push_back(HelixPose(i * 0.05));
  ToolPath out;
  ResampleOptions o;
  o.step_mm = 0.25;
  ASSERT_TRUE(ResamplePath(path, Machine(), o, &out).ok());
  // Helix length over t in [0, 2]: sqrt(20^2 + 3^2) * 2 = 40.45 mm.
  EXPECT_EQ(out.poses.size(), static_cast<size_t>(std::ceil(40.447 / 0.25)) + 1);
  EXPECT_EQ(out.poses.front().p_w_tip, path.poses.front().p_w_tip);
  EXPECT_EQ(out.poses.back().p_w_tip, path.poses.back().p_w_tip);
  for (size_t j = 1; j + 1 < out.poses.size(); ++j) {
    // The sample lies on the helix at its own parameter, within 5 um (the
    // natural end conditions cost a few um next to the ends), and
    // its axis matches the helix's axis there within 1e-4.
    const Eigen::Vector3d& p = out.poses[j].p_w_tip;
    const double t = p.z() / 3;
    const ToolPose truth = HelixPose(t);
    EXPECT_LT((p - truth.p_w_tip).norm(), 5e-3) << j;
    EXPECT_LT((out.poses[j].a_w - truth.a_w).norm(), 1e-4) << j;
    EXPECT_NEAR((p - out.poses[j - 1].p_w_tip).norm(), 40.447 / (out.poses.size() - 1), 1e-2);
    EXPECT_EQ(out.poses[j].feed_mm_per_min, 800);
  }
}

TEST(ResampleTest, KeepsRapidsAndRunsApart) {
  ToolPath path;
  for (int i = 0; i <= 10; ++i) path.poses.push_back(HelixPose(i * 0.1));
  ToolPose rapid = HelixPose(3.0);
  rapid.rapid = true;
  path.poses.push_back(rapid);
  for (int i = 1; i <= 10; ++i) path.poses.push_back(HelixPose(3.0 + i * 0.1));
  ToolPath out;
  ASSERT_TRUE(ResamplePath(path, Machine(), ResampleOptions(), &out).ok());
  int rapids = 0;
  for (const ToolPose& p : out.poses) {
    if (!p.rapid) continue;
    ++rapids;
    EXPECT_EQ(p.p_w_tip, rapid.p_w_tip);
  }
  EXPECT_EQ(rapids, 1);
  ResampleOptions bad;
  bad.step_mm = 0;
  EXPECT_FALSE(ResamplePath(path, Machine(), bad, &out).ok());
}

}  // namespace
}  // namespace tpopt
