#include "model/eval/deviation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The kinematics of data/machines/linuxcnc_xyzac_trt_sim.json (pivot 0,
// y_offset 20, z_offset 10), built by hand so that this unit does not
// depend on the JSON reader; no travel limits.
Machine SimMachine() {
  Machine m;
  m.name = "linuxcnc_xyzac_trt_sim";
  m.kinematics.y_offset_mm = 20.0;
  m.kinematics.z_offset_mm = 10.0;
  return m;
}

RuledSurface Hypar() {
  RuledSurface hypar;
  EXPECT_TRUE(
      ReadSurfaceJson(testing::SourcePath("data/surfaces/hypar.json"), &hypar)
          .ok());
  return hypar;
}

// Single-point offset by hand: tip = C1(u) + (R + offset(u)) n(u, 0), axis
// along the ruling C2(u) - C1(u) tilted by tilt(u) about the rail's
// tangent. offset and tilt are zero for a clean SPO path; a twisted
// surface then has overcut only, so the brute-force tests add smooth
// bumps that give both signs and large rotary motion.
struct SpoPerturbation {
  double offset_mm = 0.0;  // amplitude of offset(u) = a sin(3 pi u)
  double tilt_rad = 0.0;   // amplitude of tilt(u) = b sin(2 pi u)
};

ToolPath SpoPath(const RuledSurface& surface, const Cutter& cutter, int poses,
                 const SpoPerturbation& bump = {}) {
  ToolPath path;
  path.cutter = cutter;
  for (int i = 0; i < poses; ++i) {
    const double u = static_cast<double>(i) / (poses - 1);
    const Eigen::Vector3d n = surface.Normal(u, 0);
    const Eigen::Vector3d ruling = surface.Dv(u).normalized();
    const double offset = bump.offset_mm * std::sin(3 * M_PI * u);
    const Eigen::AngleAxisd tilt(bump.tilt_rad * std::sin(2 * M_PI * u),
                                 surface.Du(u, 0).normalized());
    ToolPose pose;
    pose.p_w_tip = surface.Point(u, 0) + (cutter.radius_mm + offset) * n;
    pose.a_w = (tilt * ruling).normalized();
    path.poses.push_back(pose);
  }
  return path;
}

// The hypar's SPO path (rulings vertical at u = 0.5) with its axes tilted
// alternately by +-0.3 deg about y: C swings by up to ~70 deg between
// neighbouring poses near the pole.
ToolPath ZigZagThroughThePole(const RuledSurface& hypar, const Cutter& cutter) {
  ToolPath path = SpoPath(hypar, cutter, 31);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const double tilt = (i % 2 == 0 ? 0.3 : -0.3) * kDeg;
    path.poses[i].a_w =
        Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()) * path.poses[i].a_w;
  }
  return path;
}

// Fast and brute force on the same grid agree to 1 um at every grid point
// and at the extremes; refinement only ever lowers the sampled minimum.
void ExpectAgreesWithBruteForce(const RuledSurface& surface,
                                const ToolPath& path, const Machine* machine,
                                const DeviationOptions& options,
                                int brute_substeps) {
  DeviationReport fast, brute;
  ASSERT_TRUE(
      EvaluateDeviation(surface, *path.cutter, path, machine, options, &fast)
          .ok());
  ASSERT_TRUE(EvaluateDeviationBruteForce(surface, *path.cutter, path, machine,
                                          options, brute_substeps, &brute)
                  .ok());
  EXPECT_NEAR(fast.max_overcut_mm, brute.max_overcut_mm, 1e-3);
  EXPECT_NEAR(fast.max_undercut_mm, brute.max_undercut_mm, 1e-3);
  EXPECT_NEAR(fast.rms_deviation_mm, brute.rms_deviation_mm, 1e-3);
  ASSERT_EQ(fast.u, brute.u);
  ASSERT_EQ(fast.v, brute.v);
  ASSERT_EQ(fast.deviation_mm.size(), brute.deviation_mm.size());
  for (size_t k = 0; k < fast.deviation_mm.size(); ++k) {
    EXPECT_NEAR(fast.deviation_mm[k], brute.deviation_mm[k], 1e-3)
        << "grid point " << k;
    EXPECT_LE(fast.deviation_mm[k], brute.deviation_mm[k] + 1e-9)
        << "grid point " << k;
  }
}

TEST(DeviationTest, AgreesWithBruteForceOnAPerturbedSpoPath) {
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = SpoPath(hypar, cutter, 30, {0.1, 4 * kDeg});
  DeviationOptions options;
  options.samples_u = 40;
  options.samples_v = 7;
  const Machine machine = SimMachine();
  // Both signs occur, or the comparison would prove little.
  DeviationReport report;
  ASSERT_TRUE(
      EvaluateDeviation(hypar, cutter, path, &machine, options, &report).ok());
  EXPECT_GT(report.max_overcut_mm, 0.05);
  EXPECT_GT(report.max_undercut_mm, 0.05);
  ExpectAgreesWithBruteForce(hypar, path, &machine, options, 4000);
}

TEST(DeviationTest, AgreesWithBruteForceWithATaperAndAShortFlute) {
  // The flute (18 mm) ends below rail 1 (the ruling is ~31 mm), so grid
  // points lie beyond the top cap, where the bounds are the loosest.
  const RuledSurface hypar = Hypar();
  const Cutter cutter{3.0, 18.0, 3 * kDeg};
  const ToolPath path = SpoPath(hypar, cutter, 25, {0.1, 4 * kDeg});
  DeviationOptions options;
  options.samples_u = 30;
  options.samples_v = 9;
  const Machine machine = SimMachine();
  ExpectAgreesWithBruteForce(hypar, path, &machine, options, 4000);
}

TEST(DeviationTest, AgreesWithBruteForceOnADensePath) {
  // On a twisted surface the pose that cuts q deepest lies about
  // R sin(alpha) ~ 0.8 mm of arc from q's ruling: 13 poses away on this
  // path. An evaluator that searched only the poses nearest in u would miss
  // it and under-report the overcut by half.
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = SpoPath(hypar, cutter, 1000);
  DeviationOptions options;
  options.samples_u = 9;
  options.samples_v = 5;
  const Machine machine = SimMachine();
  ExpectAgreesWithBruteForce(hypar, path, &machine, options, 16);
}

TEST(DeviationTest, AgreesWithBruteForceWithoutAMachine) {
  // Large axis turns per move (up to ~10 deg), interpolated by slerp.
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = SpoPath(hypar, cutter, 12, {0.1, 20 * kDeg});
  DeviationOptions options;
  options.samples_u = 40;
  options.samples_v = 7;
  ExpectAgreesWithBruteForce(hypar, path, nullptr, options, 4000);
}

TEST(DeviationTest, FollowsFastRotarySwingsNearThePole) {
  // The hypar's rulings pass through vertical at u = 0.5. Tilting the axes
  // alternately by +-0.3 deg about y makes C swing by up to ~70 deg
  // between neighbouring poses there; the table's offsets then carry the
  // tool along large arcs in W within one move, a gouge far from every
  // pose that a few samples per move would step over.
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = ZigZagThroughThePole(hypar, cutter);
  const Machine machine = SimMachine();
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  double largest_swing_rad = 0.0;
  for (size_t i = 1; i < joints.size(); ++i) {
    largest_swing_rad = std::max(largest_swing_rad,
                                 std::abs(joints[i][kC] - joints[i - 1][kC]));
  }
  EXPECT_GT(largest_swing_rad, 45 * kDeg);
  DeviationOptions options;
  options.samples_u = 16;
  options.samples_v = 4;
  options.u_min = 0.35;
  options.u_max = 0.65;
  DeviationReport fast, brute;
  ASSERT_TRUE(
      EvaluateDeviation(hypar, cutter, path, &machine, options, &fast).ok());
  ASSERT_TRUE(EvaluateDeviationBruteForce(hypar, cutter, path, &machine,
                                          options, 10000, &brute)
                  .ok());
  EXPECT_GT(fast.max_overcut_mm, 0.5);
  // The gouges have sharp bottoms (the end face's rim), where even 10000
  // samples a move fall short by up to ~2e-3 mm; the fast evaluator must
  // never be above the samples, and not far below them.
  for (size_t k = 0; k < fast.deviation_mm.size(); ++k) {
    EXPECT_LE(fast.deviation_mm[k], brute.deviation_mm[k] + 1e-9)
        << "grid point " << k;
    EXPECT_GE(fast.deviation_mm[k], brute.deviation_mm[k] - 2e-3)
        << "grid point " << k;
  }
}

// TCP motion through the pole: the fast evaluator agrees with brute force and
// with an independent sampling of the closed form (tip linear in W, A and C
// linear), and differs from the joint model there, where the table's swing
// of C carries a joint-linear tip off its chord.
TEST(DeviationTest, TcpMotionNearThePoleFollowsItsClosedForm) {
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = ZigZagThroughThePole(hypar, cutter);
  const Machine machine = SimMachine();
  DeviationOptions options;
  options.samples_u = 16;
  options.samples_v = 4;
  options.u_min = 0.4;
  options.u_max = 0.6;
  options.interpolation = Interpolation::kTcp;
  ExpectAgreesWithBruteForce(hypar, path, &machine, options, 2000);
  DeviationReport tcp, joint;
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, path, &machine, options, &tcp).ok());
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  const size_t nv = tcp.v.size();
  for (size_t k = 0; k < tcp.deviation_mm.size(); k += 7) {
    const Eigen::Vector3d q = hypar.Point(tcp.u[k / nv], tcp.v[k % nv]);
    double least = 1e9;
    for (size_t i = 0; i + 1 < path.poses.size(); ++i) {
      for (int step = 0; step <= 400; ++step) {
        const double s = step / 400.0;
        const JointVector j = (1 - s) * joints[i] + s * joints[i + 1];
        const Eigen::Vector3d tip = (1 - s) * path.poses[i].p_w_tip + s * path.poses[i + 1].p_w_tip;
        least = std::min(least, SignedDistanceToCutter<double>(
                                    cutter, q, tip, AnglesToAxis(j[kA], j[kC])));
      }
    }
    EXPECT_LE(tcp.deviation_mm[k], least + 1e-9) << "grid point " << k;
    EXPECT_NEAR(tcp.deviation_mm[k], least, 2e-3) << "grid point " << k;
  }
  options.interpolation = Interpolation::kJoint;
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, path, &machine, options, &joint).ok());
  EXPECT_GT(joint.max_overcut_mm, tcp.max_overcut_mm + 0.1);
}

TEST(DeviationTest, MachineMotionDiffersFromSlerpMotion) {
  // The same poses, cut by the machine (joints linear) and by the slerp
  // motion, agree at the poses but not between them: the evaluator really
  // follows the joints.
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = SpoPath(hypar, cutter, 12, {0.0, 20 * kDeg});
  const Machine machine = SimMachine();
  DeviationReport joints, slerp;
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, path, &machine,
                                DeviationOptions(), &joints)
                  .ok());
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, path, nullptr,
                                DeviationOptions(), &slerp)
                  .ok());
  double largest_difference = 0.0;
  for (size_t k = 0; k < joints.deviation_mm.size(); ++k) {
    largest_difference =
        std::max(largest_difference,
                 std::abs(joints.deviation_mm[k] - slerp.deviation_mm[k]));
  }
  EXPECT_GT(largest_difference, 1e-3);
}

// A cylinder patch: both rails the same arc (a cubic B-spline through
// points of a circle of radius 30), rail 1 shifted by (5, 0, 20) so that
// the rulings lean and A stays away from the pole. Whatever the rail, a
// surface whose rulings are all parallel is developable, so a
// single-point-offset cutter is tangent along the whole ruling and the
// swept deviation vanishes up to the chord error between poses.
RuledSurface CylinderPatch(CutterSide side) {
  std::vector<Eigen::Vector3d> c1_points, c2_points;
  for (int k = 0; k <= 8; ++k) {
    const double phi = (-40.0 + 10.0 * k) * kDeg;
    const Eigen::Vector3d p(30 * std::sin(phi), 30 * std::cos(phi), 0);
    c1_points.push_back(p);
    c2_points.push_back(p + Eigen::Vector3d(5, 0, 20));
  }
  const std::vector<double> knots = {
      0,         0,         0, 0, 1.0 / 6.0, 2.0 / 6.0, 3.0 / 6.0,
      4.0 / 6.0, 5.0 / 6.0, 1, 1, 1,         1};
  BSplineCurve c1, c2;
  EXPECT_TRUE(BSplineCurve::Create(3, knots, c1_points, "c1", &c1).ok());
  EXPECT_TRUE(BSplineCurve::Create(3, knots, c2_points, "c2", &c2).ok());
  return RuledSurface("cylinder", c1, c2, side);
}

TEST(DeviationTest, SpoOnACylinderPatchIsExact) {
  const Cutter cutter{4.0, 30.0, 0.0};
  const Machine machine = SimMachine();
  // Convex side (outside the arch) and concave side (inside, R < 30).
  for (CutterSide side : {CutterSide::kPositive, CutterSide::kNegative}) {
    const RuledSurface cylinder = CylinderPatch(side);
    EXPECT_LT(std::abs(cylinder.GaussianCurvature(0.5, 0.5)), 1e-12);
    const ToolPath path = SpoPath(cylinder, cutter, 200);
    DeviationOptions options;
    options.samples_u = 60;
    options.samples_v = 6;
    for (const Machine* m : {&machine, static_cast<const Machine*>(nullptr)}) {
      DeviationReport report;
      ASSERT_TRUE(
          EvaluateDeviation(cylinder, cutter, path, m, options, &report).ok());
      EXPECT_LT(report.max_overcut_mm, 1e-3);
      EXPECT_LT(report.max_undercut_mm, 1e-3);
    }
  }
}

// The plane y = 0, x in [0, 30], z in [0, 10], cut from +y.
RuledSurface PlaneY0() {
  BSplineCurve c1, c2;
  EXPECT_TRUE(
      BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {30, 0, 0}}, "c1", &c1)
          .ok());
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 10}, {30, 0, 10}},
                                   "c2", &c2)
                  .ok());
  // r_u x r_v = x cross z = -y: the +y side is "negative".
  return RuledSurface("plane", c1, c2, CutterSide::kNegative);
}

ToolPose VerticalPose(double x_mm, double y_mm, bool rapid = false) {
  ToolPose pose;
  pose.p_w_tip = Eigen::Vector3d(x_mm, y_mm, 0);
  pose.rapid = rapid;
  return pose;
}

TEST(DeviationTest, ToolMovingAlongAPlaneLeavesItsOffset) {
  // A vertical tool moving along x at R + 0.05 from the plane leaves 0.05
  // (undercut) everywhere; at R - 0.05 it cuts 0.05 too deep (overcut).
  const RuledSurface plane = PlaneY0();
  const Machine machine = SimMachine();
  for (double offset : {0.05, -0.05}) {
    ToolPath path;
    path.cutter = Cutter{4.0, 20.0, 0.0};
    for (int i = 0; i <= 30; ++i) {
      path.poses.push_back(VerticalPose(i, 4.0 + offset));
    }
    for (const Machine* m : {&machine, static_cast<const Machine*>(nullptr)}) {
      DeviationReport r;
      ASSERT_TRUE(EvaluateDeviation(plane, *path.cutter, path, m,
                                    DeviationOptions(), &r)
                      .ok());
      EXPECT_EQ(r.u.front(), 0.0);
      EXPECT_EQ(r.u.back(), 1.0);
      for (double d : r.deviation_mm) ASSERT_NEAR(d, offset, 1e-9);
      EXPECT_NEAR(r.rms_deviation_mm, 0.05, 1e-9);
      EXPECT_NEAR(offset > 0 ? r.max_undercut_mm : r.max_overcut_mm, 0.05,
                  1e-9);
      EXPECT_EQ(offset > 0 ? r.max_overcut_mm : r.max_undercut_mm, 0.0);
    }
  }
}

TEST(DeviationTest, StaticPoseMatchesTheDistanceToItsAxis) {
  // One pose held still (two equal poses) at x = 15, y = R + offset. A
  // plane point (x, 0, z) is sqrt((x - 15)^2 + (R + offset)^2) from the
  // axis, so its deviation is that minus R: the offset on the line x = 15.
  const RuledSurface plane = PlaneY0();
  const Machine machine = SimMachine();
  const double r = 4.0;
  for (double offset : {0.05, -0.05}) {
    ToolPath path;
    path.cutter = Cutter{r, 20.0, 0.0};
    path.poses = {VerticalPose(15, r + offset), VerticalPose(15, r + offset)};
    DeviationOptions options;
    options.samples_u = 21;
    options.u_min = 0.4;  // x in [12, 18]
    options.u_max = 0.6;
    for (const Machine* m : {&machine, static_cast<const Machine*>(nullptr)}) {
      DeviationReport report;
      ASSERT_TRUE(
          EvaluateDeviation(plane, *path.cutter, path, m, options, &report)
              .ok());
      for (size_t iu = 0; iu < report.u.size(); ++iu) {
        const double dx = 30 * report.u[iu] - 15;
        const double expected = std::hypot(dx, r + offset) - r;
        for (size_t iv = 0; iv < report.v.size(); ++iv) {
          ASSERT_NEAR(report.At(iu, iv), expected, 1e-9) << iu << " " << iv;
        }
      }
      // The deepest cut (or the least material left) is on the axis line.
      const double least = *std::min_element(report.deviation_mm.begin(),
                                             report.deviation_mm.end());
      EXPECT_NEAR(least, offset, 1e-9);
      if (offset < 0) {
        EXPECT_NEAR(report.max_overcut_mm, -offset, 1e-9);
        EXPECT_NEAR(report.overcut_u, 0.5, 1e-12);
      }
    }
  }
}

TEST(DeviationTest, MovesIntoARapidPoseDoNotCut) {
  // Two passes, x 0..10 and x 20..30, at R + 0.05; the rapid between them
  // would leave 0.05 at x = 15 if it cut. It does not, so there the
  // nearest tools are the passes' ends, 5 mm away along x.
  const RuledSurface plane = PlaneY0();
  const double r = 4.0, y = r + 0.05;
  ToolPath path;
  path.cutter = Cutter{r, 20.0, 0.0};
  for (int x = 0; x <= 10; ++x) path.poses.push_back(VerticalPose(x, y));
  path.poses.push_back(VerticalPose(20, y, /*rapid=*/true));
  for (int x = 21; x <= 30; ++x) path.poses.push_back(VerticalPose(x, y));
  DeviationOptions options;
  options.samples_u = 31;  // x = 0, 1, ..., 30
  options.samples_v = 3;
  DeviationReport report;
  ASSERT_TRUE(
      EvaluateDeviation(plane, *path.cutter, path, nullptr, options, &report)
          .ok());
  EXPECT_NEAR(report.At(15, 1), std::hypot(5.0, y) - r, 1e-9);
  EXPECT_NEAR(report.At(12, 1), std::hypot(2.0, y) - r, 1e-9);
  EXPECT_NEAR(report.At(5, 1), 0.05, 1e-9);
  EXPECT_NEAR(report.At(25, 1), 0.05, 1e-9);
  EXPECT_EQ(report.undercut_u, 0.5);
}

// Two tools, each at its own radius + 0.05 from the plane: a pass of tool
// 1 (R 4) over x in [0, 14], a rapid, a pass of tool 2 (R 2) over x in
// [16, 30]. With a cutter a tool, each pass leaves 0.05 along it, and at
// x = 15 the nearer pass end: min over the tools of hypot(1, R + 0.05) - R.
// With one cutter (R 4) for both, tool 2's pass would cut 4 - 2.05 deep.
TEST(DeviationTest, EachMoveIsCutByItsOwnToolWhenAsked) {
  const RuledSurface plane = PlaneY0();
  const Machine machine = SimMachine();
  const double r1 = 4.0, r2 = 2.0, offset = 0.05;
  ToolPath path;
  path.tools.push_back({1, Cutter{r1, 20.0, 0.0}, 0.0, 3});
  path.tools.push_back({2, Cutter{r2, 20.0, 0.0}, 0.0, 40});
  path.cutter = path.tools[0].cutter;
  for (int x = 0; x <= 14; ++x) {
    path.poses.push_back(VerticalPose(x, r1 + offset));
    path.poses.back().tool = 0;
  }
  for (int x = 16; x <= 30; ++x) {
    path.poses.push_back(VerticalPose(x, r2 + offset, /*rapid=*/x == 16));
    path.poses.back().tool = 1;
  }
  DeviationOptions options;
  options.samples_u = 31;  // x = 0, 1, ..., 30
  options.samples_v = 3;
  options.cutter_per_tool = true;
  const double at_15 = std::min(std::hypot(1.0, r1 + offset) - r1, std::hypot(1.0, r2 + offset) - r2);
  for (const Machine* m : {&machine, static_cast<const Machine*>(nullptr)}) {
    DeviationReport report, brute;
    ASSERT_TRUE(EvaluateDeviation(plane, *path.cutter, path, m, options, &report).ok());
    for (int x : {0, 7, 14, 16, 23, 30}) EXPECT_NEAR(report.At(x, 1), offset, 1e-9) << x;
    EXPECT_NEAR(report.At(15, 1), at_15, 1e-9);
    EXPECT_EQ(report.max_overcut_mm, 0.0);
    ASSERT_TRUE(EvaluateDeviationBruteForce(plane, *path.cutter, path, m, options, 16, &brute).ok());
    for (size_t k = 0; k < brute.deviation_mm.size(); ++k) {
      EXPECT_NEAR(report.deviation_mm[k], brute.deviation_mm[k], 1e-9) << k;
    }
    // The one cutter given, for every move.
    DeviationOptions one = options;
    one.cutter_per_tool = false;
    ASSERT_TRUE(EvaluateDeviation(plane, *path.cutter, path, m, one, &report).ok());
    EXPECT_NEAR(report.At(23, 1), r2 + offset - r1, 1e-9);
    EXPECT_NEAR(report.max_overcut_mm, r1 - r2 - offset, 1e-9);
  }
}

// A path that stops short of the surface's end, judged on the range its
// input covered, is charged for the material it leaves there; judged on its
// own range it would look clean.
TEST(DeviationTest, PathStoppingShortIsChargedOnTheInputsRange) {
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath full = SpoPath(hypar, cutter, 41);
  ToolPath short_path = full;
  short_path.poses.resize(33);  // u = 0 .. 0.8
  double lo = 0, hi = 0;
  ASSERT_TRUE(CoveredRangeU(hypar, full, &lo, &hi));
  EXPECT_NEAR(lo, 0.0, 1e-9);
  EXPECT_NEAR(hi, 1.0, 1e-9);
  double short_lo = 0, short_hi = 0;
  ASSERT_TRUE(CoveredRangeU(hypar, short_path, &short_lo, &short_hi));
  EXPECT_NEAR(short_hi, 0.8, 1e-6);
  DeviationOptions own;
  own.samples_u = 41;
  own.samples_v = 5;
  DeviationOptions input_range = own;
  input_range.u_min = lo;
  input_range.u_max = hi;
  const Machine machine = SimMachine();
  DeviationReport on_own, on_input, brute;
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, short_path, &machine, own, &on_own).ok());
  ASSERT_TRUE(
      EvaluateDeviation(hypar, cutter, short_path, &machine, input_range, &on_input).ok());
  ASSERT_TRUE(EvaluateDeviationBruteForce(hypar, cutter, short_path, &machine, input_range, 64,
                                          &brute)
                  .ok());
  // The last pose's cutter at u = 0.8 is far from the u = 1 ruling: the
  // distance from C1(1) to that static cutter bounds the grid's undercut
  // from below (no other pose comes nearer: the path runs away from it).
  const ToolPose& last = short_path.poses.back();
  const double to_last_mm =
      SignedDistanceToCutter<double>(cutter, hypar.Point(1.0, 0.0), last.p_w_tip, last.a_w);
  EXPECT_GT(to_last_mm, 1.0);
  EXPECT_LT(on_own.max_undercut_mm, 0.05);
  EXPECT_DOUBLE_EQ(on_input.u.back(), 1.0);
  EXPECT_GE(on_input.max_undercut_mm, to_last_mm - 1e-9);
  EXPECT_NEAR(on_input.max_undercut_mm, brute.max_undercut_mm, 1e-3);
  EXPECT_DOUBLE_EQ(on_input.undercut_u, 1.0);
  // No cutting move: no range.
  ToolPath one_pose = full;
  one_pose.poses.resize(1);
  EXPECT_FALSE(CoveredRangeU(hypar, one_pose, &lo, &hi));
}

TEST(DeviationTest, RejectsBadInput) {
  const RuledSurface hypar = Hypar();
  const Cutter cutter;
  DeviationReport report;
  // Only a rapid move: nothing is cut.
  ToolPath path;
  path.poses.resize(2);
  path.poses[1].rapid = true;
  EXPECT_FALSE(EvaluateDeviation(hypar, cutter, path, nullptr,
                                 DeviationOptions(), &report)
                   .ok());
  // Bad options.
  path.poses[1] = VerticalPose(1, 5);
  DeviationOptions options;
  options.samples_v = 1;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("1"), std::string::npos) << why;
  EXPECT_FALSE(
      EvaluateDeviation(hypar, cutter, path, nullptr, options, &report).ok());
  options = DeviationOptions();
  options.u_min = 0.5;  // u_max left NaN
  EXPECT_FALSE(options.IsValid(&why));
  options.u_max = 0.4;
  EXPECT_FALSE(options.IsValid(&why));
  options.u_max = 0.6;
  EXPECT_TRUE(options.IsValid(&why));
  // A non-unit axis (without a machine, which would check it itself).
  path.poses[1].a_w = Eigen::Vector3d(0, 0, 2);
  path.poses[1].source_line = 7;
  Status s = EvaluateDeviation(hypar, cutter, path, nullptr, DeviationOptions(),
                               &report);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 1 (line 7)"), std::string::npos)
      << s.message();
  // Half a turn of the axis in one move has no defined motion.
  path.poses[1].a_w = -Eigen::Vector3d::UnitZ();
  s = EvaluateDeviation(hypar, cutter, path, nullptr, DeviationOptions(),
                        &report);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 1"), std::string::npos) << s.message();
  // A bad cutter.
  path.poses[1].a_w = Eigen::Vector3d::UnitZ();
  EXPECT_FALSE(EvaluateDeviation(hypar, Cutter{-1.0, 20.0, 0.0}, path, nullptr,
                                 DeviationOptions(), &report)
                   .ok());
}

TEST(DeviationTest, JointOverloadMatchesMachinePointerOverload) {
  const RuledSurface hypar = Hypar();
  const Cutter cutter{4.0, 40.0, 0.0};
  const ToolPath path = SpoPath(hypar, cutter, 30, {0.1, 4 * kDeg});
  const Machine machine = SimMachine();
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  DeviationReport a, b;
  ASSERT_TRUE(EvaluateDeviation(hypar, cutter, path, machine, joints,
                                DeviationOptions(), &a)
                  .ok());
  ASSERT_TRUE(
      EvaluateDeviation(hypar, cutter, path, &machine, DeviationOptions(), &b)
          .ok());
  EXPECT_EQ(a.deviation_mm, b.deviation_mm);
}

}  // namespace
}  // namespace tpopt
