#include "model/deviation.h"

#include <gtest/gtest.h>

#include "model/json_io.h"
#include "model/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

Machine SimMachine() {
  Machine m;
  EXPECT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &m)
                  .ok());
  return m;
}

struct Evaluated {
  DeviationReport fast, brute;
};

Evaluated EvaluateBoth(const RuledSurface& surface, const ToolPath& path, const Machine& m,
                       const DeviationOptions& o) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(m.AssignJoints(path, &joints).ok());
  Evaluated e;
  EXPECT_TRUE(EvaluateDeviation(surface, *path.cutter, path, m, joints, o, &e.fast).ok());
  EXPECT_TRUE(
      EvaluateDeviationBruteForce(surface, *path.cutter, path, m, joints, o, 4000, &e.brute).ok());
  return e;
}

TEST(DeviationTest, AgreesWithBruteForceToOneMicron) {
  RuledSurface hypar;
  ASSERT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/hypar.json"), &hypar).ok());
  FlankPathOptions g;
  g.poses = 30;
  g.uv_distortion = 0.05;  // a gouging stretch, so both signs occur
  g.distortion_width = 0.3;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(hypar, g, &path).ok());
  DeviationOptions o;
  o.samples_u = 40;
  o.samples_v = 7;
  const Evaluated e = EvaluateBoth(hypar, path, SimMachine(), o);
  EXPECT_GT(e.fast.max_overcut_mm, 0.01);
  EXPECT_GT(e.fast.max_undercut_mm, 0.01);
  EXPECT_NEAR(e.fast.max_overcut_mm, e.brute.max_overcut_mm, 1e-3);
  EXPECT_NEAR(e.fast.max_undercut_mm, e.brute.max_undercut_mm, 1e-3);
  ASSERT_EQ(e.fast.deviation_mm.size(), e.brute.deviation_mm.size());
  for (size_t k = 0; k < e.fast.deviation_mm.size(); ++k) {
    EXPECT_NEAR(e.fast.deviation_mm[k], e.brute.deviation_mm[k], 1e-3) << "grid point " << k;
    // Refinement can only find a lower minimum than the samples.
    EXPECT_LE(e.fast.deviation_mm[k], e.brute.deviation_mm[k] + 1e-12) << "grid point " << k;
  }
}

TEST(DeviationTest, SpoOnACylinderPatchIsExact) {
  // A developable surface: the same quadratic arc at z = 0 and z = 25.
  BSplineCurve c1, c2;
  ASSERT_TRUE(BSplineCurve::Create(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {20, 15, 0}, {40, 0, 0}},
                                   "c1", &c1)
                  .ok());
  ASSERT_TRUE(BSplineCurve::Create(2, {0, 0, 0, 1, 1, 1},
                                   {{0, 0, 25}, {20, 15, 25}, {40, 0, 25}}, "c2", &c2)
                  .ok());
  // Cutter outside the arch (convex side), so the swept cylinder is tangent.
  const RuledSurface cylinder("cylinder", c1, c2, CutterSide::kNegative);
  FlankPathOptions g;
  g.poses = 200;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(cylinder, g, &path).ok());
  DeviationOptions o;
  o.samples_u = 50;
  o.samples_v = 6;
  Machine m;
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  DeviationReport r;
  ASSERT_TRUE(EvaluateDeviation(cylinder, *path.cutter, path, m, joints, o, &r).ok());
  EXPECT_LT(r.max_overcut_mm, 1e-3);
  EXPECT_LT(r.max_undercut_mm, 1e-3);
}

TEST(DeviationTest, OffsetPlaneGivesTheOffset) {
  // A plane y = 0 cut from +y by a vertical tool moving along x at a
  // distance R + 0.05 (undercut 0.05) or R - 0.05 (overcut 0.05).
  BSplineCurve c1, c2;
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {30, 0, 0}}, "c1", &c1).ok());
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 10}, {30, 0, 10}}, "c2", &c2).ok());
  const RuledSurface plane("plane", c1, c2, CutterSide::kNegative);
  for (double offset : {0.05, -0.05}) {
    ToolPath path;
    path.cutter = Cutter{4.0, 20.0, 0.0};
    for (int i = 0; i <= 30; ++i) {
      ToolPose pose;
      pose.p_w_tip = Eigen::Vector3d(i, 4.0 + offset, 0);
      path.poses.push_back(pose);
    }
    Machine m;
    std::vector<JointVector> joints;
    ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
    DeviationReport r;
    ASSERT_TRUE(EvaluateDeviation(plane, *path.cutter, path, m, joints, DeviationOptions(), &r).ok());
    for (double d : r.deviation_mm) ASSERT_NEAR(d, offset, 1e-9);
    EXPECT_NEAR(r.rms_deviation_mm, 0.05, 1e-9);
    EXPECT_NEAR(offset > 0 ? r.max_undercut_mm : r.max_overcut_mm, 0.05, 1e-9);
  }
}

TEST(DeviationTest, RejectsAPathWithoutCuttingMoves) {
  RuledSurface hypar;
  ASSERT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/hypar.json"), &hypar).ok());
  ToolPath path;
  path.poses.resize(2);
  path.poses[1].rapid = true;
  Machine m;
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  DeviationReport r;
  EXPECT_FALSE(EvaluateDeviation(hypar, Cutter(), path, m, joints, DeviationOptions(), &r).ok());
}

}  // namespace
}  // namespace tpopt
