// Straight through the A = 0 pole: the plane fitted to a passage that
// misses the pole, the axes put on it, and the spline mode that does so on
// the hypar's distorted CAM path.
#include "solver/spline/pole_crossing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/eval/path_metrics.h"
#include "solver/spline/spline_smoother.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kPlaneC = 30 * kDeg;  // azimuth of the true crossing plane
constexpr double kPoleAngle = 5 * kDeg;

// The horizontal unit vector at azimuth c, by the machine's convention
// a = (sA sC, sA cC, cA).
Eigen::Vector3d Horizontal(double c) { return {std::sin(c), std::cos(c), 0.0}; }

// The axis that crosses the plane of azimuth kPlaneC at tilt `tilt` (signed,
// towards Horizontal(kPlaneC)) before it is pushed `miss` off the plane:
// cos(miss) (sin(tilt) d + cos(tilt) z) + sin(miss) m, with d, m the plane's
// horizontal direction and normal. Its component along m is sin(miss) and
// its projection onto the plane is sin(tilt) d + cos(tilt) z exactly.
Eigen::Vector3d MissingAxis(double tilt, double miss) {
  const Eigen::Vector3d on_plane = std::sin(tilt) * Horizontal(kPlaneC) +
                                   std::cos(tilt) * Eigen::Vector3d::UnitZ();
  return std::cos(miss) * on_plane +
         std::sin(miss) * Horizontal(kPlaneC + M_PI / 2);
}

// 61 poses along a straight xy line, tilting from +12 to -12 deg through the
// pole along the plane, each `miss` off it. The tilts are symmetric about
// the middle pose, so the passage (tilt within about 5 deg) is too, and its
// xy points' second moment has the plane's direction as an exact principal
// axis.
double Tilt(int i) { return (12.0 - 0.4 * i) * kDeg; }

ToolPath MissingPath(double miss) {
  ToolPath path;
  for (int i = 0; i <= 60; ++i) {
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(0.5 * i, 0.2 * i, 0.0);
    pose.a_w = MissingAxis(Tilt(i), miss);
    path.poses.push_back(pose);
  }
  return path;
}

TEST(PoleCrossingTest, PutsEachAxisOnThePlaneMovingItByItsMiss) {
  const double miss = 0.6 * kDeg;
  const ToolPath path = MissingPath(miss);
  const std::vector<PolePassage> passages = FindPolePassages(path, kPoleAngle);
  ASSERT_EQ(passages.size(), 1u);
  const PolePassage& passage = passages[0];
  // Tilt within 5 deg (to the miss): poses 18..42, symmetric about 30.
  EXPECT_EQ(passage.first, 18u);
  EXPECT_EQ(passage.last, 42u);

  const PoleCrossing crossing = FitPoleCrossing(path, passage);
  EXPECT_NEAR(crossing.plane_c_rad, kPlaneC, 1e-12);
  EXPECT_NEAR(crossing.miss_rad, miss, 1e-12);

  ToolPath routed = path;
  RouteThroughPole(crossing, &routed);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const Eigen::Vector3d& before = path.poses[i].a_w;
    const Eigen::Vector3d& after = routed.poses[i].a_w;
    EXPECT_EQ(routed.poses[i].p_w_tip, path.poses[i].p_w_tip) << i;
    if (i < passage.first || i > passage.last) {
      EXPECT_EQ(after, before) << i;
      continue;
    }
    EXPECT_LT((after - AnglesToAxis(Tilt(i), kPlaneC)).norm(), 1e-12) << i;
    const double turned =
        std::atan2(before.cross(after).norm(), before.dot(after));
    EXPECT_NEAR(turned, miss, 1e-12) << i;
  }

  // On the machine: C held across the passage and A through zero, where the
  // input swung C by nearly half a turn.
  Machine machine;
  std::vector<double> a, c, a_in, c_in;
  ASSERT_TRUE(
      machine.AssignRotaryAngles(routed, 0, routed.poses.size(), &a, &c).ok());
  ASSERT_TRUE(
      machine.AssignRotaryAngles(path, 0, path.poses.size(), &a_in, &c_in)
          .ok());
  // The input's azimuth turns from atan(tan(miss) / sin(tilt)) off the
  // plane to as far off its other side.
  const double off = std::atan2(std::tan(miss), std::sin(Tilt(passage.first)));
  EXPECT_NEAR(std::abs(c_in[passage.last] - c_in[passage.first]),
              M_PI - 2 * off, 1e-9);
  for (size_t i = passage.first; i <= passage.last; ++i) {
    EXPECT_NEAR(c[i], c[passage.first], 1e-9) << i;
    EXPECT_NEAR(a[i] * a[passage.first], Tilt(i) * Tilt(passage.first), 1e-12)
        << i;
  }
  EXPECT_LT(a[passage.first] * a[passage.last], 0.0);
}

// Spline mode routes a passage through the pole only within the bound, and
// only where the A travel has room for the sign change of A.
TEST(PoleCrossingTest, SplineModeRoutesWithinTheBoundAndTheATravel) {
  const ToolPath path = MissingPath(0.6 * kDeg);
  const Cutter cutter{4.0, 30.0, 0.0};
  Machine machine;
  SplineSmootherOptions options;
  options.pole_crossing_deg = 0.7;
  auto crossings = [&](const Machine& m, const SplineSmootherOptions& o) {
    ToolPath out;
    SplineSmootherReport report;
    EXPECT_TRUE(
        SmoothWithSplines(path, m, nullptr, cutter, o, &out, &report).ok());
    return report.pole_crossings;
  };
  EXPECT_EQ(crossings(machine, options), 1);
  SplineSmootherOptions tight = options;
  tight.pole_crossing_deg = 0.5;
  EXPECT_EQ(crossings(machine, tight), 0);
  SplineSmootherOptions off = options;
  off.pole_crossing_deg = 0.0;
  EXPECT_EQ(crossings(machine, off), 0);
  Machine a_positive = machine;
  a_positive.limits[kA].min = 0.0;
  EXPECT_EQ(crossings(a_positive, options), 0);
}

// The hypar's single-point-offset path crosses the pole along a plane; the
// CAM-like U/V bump pushes it up to 3.4 deg off that plane, and C then spins
// half a turn in a few mm (peak d2C/ds2 257 deg/mm^2), which the A/C spline
// fit alone only brings to 34 deg/mm^2, at a 0.165 mm overcut. Through the
// pole, C is held (measured: 0.000 deg/mm^2) and the overcut comes back to
// the clean path's (measured 0.0804 mm against 0.0777 mm).
TEST(PoleCrossingTest, HyparBumpPathCrossesThePoleWithCHeld) {
  RuledSurface surface;
  Machine machine;
  ASSERT_NO_FATAL_FAILURE(testing::LoadHyparBench(&surface, &machine));
  FlankPathOptions g;
  ToolPath clean, cam;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &clean).ok());
  g.uv_distortion = 0.03;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &cam).ok());
  ToolPath out;
  SplineSmootherReport report;
  ASSERT_TRUE(SmoothWithSplines(cam, machine, &surface, *cam.cutter,
                                SplineSmootherOptions(), &out, &report)
                  .ok());
  EXPECT_EQ(report.pole_crossings, 1);
  auto metrics = [&](const ToolPath& path) {
    PathMetrics m;
    EXPECT_TRUE(EvaluatePath(path, machine, &surface, *cam.cutter,
                             DeviationOptions(), MotionOptions(), &m)
                    .ok());
    return m;
  };
  const PathMetrics in = metrics(cam), smooth = metrics(out),
                    reference = metrics(clean);
  const double c_in = in.motion.axes[kC].peak_second_derivative_per_mm2 / kDeg;
  const double c_out =
      smooth.motion.axes[kC].peak_second_derivative_per_mm2 / kDeg;
  EXPECT_GT(c_in, 200.0);
  EXPECT_LT(c_out, 1.0);
  EXPECT_LT(smooth.motion.axes[kA].peak_second_derivative_per_mm2 / kDeg, 0.1);
  EXPECT_LT(WorstDeviationMm(smooth), 1.1 * WorstDeviationMm(reference));
}

}  // namespace
}  // namespace tpopt
