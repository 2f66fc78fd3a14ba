#include "solver/smooth/surface_placement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/eval/path_metrics.h"
#include "solver/spline/overhang.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

// The impeller blade's DPO path of 80 poses (noisy and U/V-distorted when
// asked), each tip moved `overhang_mm` down its axis as CAM writes flank
// paths that cut the whole ruling.
ToolPath BladePath(const RuledSurface& surface, double axis_noise_deg, double uv_bump,
                   double overhang_mm) {
  FlankPathOptions g;
  g.strategy = FlankStrategy::kDoublePointOffset;
  g.poses = 80;
  g.axis_noise_deg = axis_noise_deg;
  g.uv_distortion = uv_bump;
  g.distortion_width = 0.3;
  ToolPath path;
  EXPECT_TRUE(GenerateFlankPath(surface, g, &path).ok());
  for (ToolPose& p : path.poses) p.p_w_tip -= overhang_mm * p.a_w;
  return path;
}

class SurfacePlacementTest : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::LoadImpellerBench(&surface_, &machine_);
    cutter_.radius_mm = 4.0;
    cutter_.flute_length_mm = 80.0;
  }
  double MaxDeviationMm(const ToolPath& path) {
    PathMetrics m;
    EXPECT_TRUE(EvaluatePath(path, machine_, &surface_, cutter_, DeviationOptions(),
                             MotionOptions(), &m)
                    .ok());
    return WorstDeviationMm(m);
  }
  RuledSurface surface_;
  Machine machine_;
  Cutter cutter_;
};

// A clean DPO path with its tips on the floor (whose foot on rail 0 is its
// contact) comes back as itself: the same axes, and tips that move only
// along their axes (by the fitted overhang, solver/spline/overhang.h, which
// follows the pose heights within kOverhangNoiseMm; the DPO tip sits a
// little above the floor along its tilted axis).
TEST_F(SurfacePlacementTest, ACleanDpoPathKeepsItsAxesAndItsTipsOnThem) {
  const ToolPath in = BladePath(surface_, 0.0, 0.0, 0.0);
  ToolPath placed;
  ASSERT_TRUE(PlaceOnSurface(in, surface_, cutter_, &placed).ok());
  ASSERT_EQ(placed.poses.size(), in.poses.size());
  for (size_t i = 0; i < in.poses.size(); ++i) {
    const ToolPose& a = in.poses[i];
    const ToolPose& b = placed.poses[i];
    EXPECT_LT((a.a_w - b.a_w).norm(), 1e-9) << i;
    const Eigen::Vector3d d = b.p_w_tip - a.p_w_tip;
    EXPECT_LT(d.cross(a.a_w).norm(), 1e-9) << i;
    EXPECT_LE(std::abs(d.dot(a.a_w)), kOverhangNoiseMm) << i;
  }
}

// The CAM noise (0.3 deg on the axis), a U/V mismatch and a 2 mm overhang
// leave the input 2.7 x the clean DPO path's deviation off the surface;
// placed at their contacts (found from the noisy axes, so a little off the
// clean path's u), the poses come within 1.2 x of the clean path, by the
// brute-force evaluator (measured: 1.14 x).
TEST_F(SurfacePlacementTest, ANoisyPathIsPlacedAsNearTheSurfaceAsTheCleanDpoPath) {
  const ToolPath in = BladePath(surface_, 0.3, 0.03, 2.0);
  const ToolPath clean = BladePath(surface_, 0.0, 0.0, 2.0);
  ToolPath placed;
  ASSERT_TRUE(PlaceOnSurface(in, surface_, cutter_, &placed).ok());
  const double dev_in = MaxDeviationMm(in), dev_clean = MaxDeviationMm(clean);
  const double dev_placed = MaxDeviationMm(placed);
  EXPECT_GT(dev_in, 2 * dev_clean);
  EXPECT_LT(dev_placed, 1.2 * dev_clean) << "input " << dev_in << " clean " << dev_clean;
  EXPECT_LT(dev_placed, 0.5 * dev_in);
}

// Lead-in poses in the air beyond the surface's end follow the first pose
// on it rigidly, and a rapid target keeps its place.
TEST_F(SurfacePlacementTest, LeadPosesFollowTheirCutRigidlyAndRapidTargetsStay) {
  ToolPath in = BladePath(surface_, 0.3, 0.0, 2.0);
  const Eigen::Vector3d out_w = -surface_.rail(0).Evaluate(0.0, 1)[1].normalized();
  const ToolPose first = in.poses.front();
  for (int k = 1; k <= 2; ++k) {
    ToolPose lead = first;
    lead.p_w_tip += 3.0 * k * out_w;
    in.poses.insert(in.poses.begin(), lead);
  }
  in.poses[50].rapid = true;
  ToolPath placed;
  ASSERT_TRUE(PlaceOnSurface(in, surface_, cutter_, &placed).ok());
  EXPECT_TRUE(BeyondRailEnd(surface_, in.poses[0], 0.0));
  EXPECT_TRUE(BeyondRailEnd(surface_, in.poses[1], 0.0));
  EXPECT_FALSE(BeyondRailEnd(surface_, in.poses[2], 0.0));
  const ToolPose& on = placed.poses[2];
  EXPECT_GT((on.a_w - in.poses[2].a_w).norm(), 1e-4);  // the noise is gone
  for (int k = 0; k < 2; ++k) {
    const ToolPose& lead = placed.poses[k];
    EXPECT_LT((lead.a_w - on.a_w).norm(), 1e-12) << k;
    EXPECT_NEAR((lead.p_w_tip - on.p_w_tip).norm(), 3.0 * (2 - k), 1e-9) << k;
    // The lead line turns with the pose it follows.
    const Eigen::Vector3d turned =
        Eigen::Quaterniond::FromTwoVectors(in.poses[2].a_w, on.a_w) * out_w;
    EXPECT_LT(((lead.p_w_tip - on.p_w_tip).normalized() - turned).norm(), 1e-9) << k;
  }
  EXPECT_EQ(placed.poses[50].p_w_tip, in.poses[50].p_w_tip);
  EXPECT_EQ(placed.poses[50].a_w, in.poses[50].a_w);
}

}  // namespace
}  // namespace tpopt
