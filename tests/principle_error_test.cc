#include "model/eval/principle_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "model/cutter/cutter.h"
#include "model/eval/deviation.h"
#include "model/geometry/ruled_surface.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Eqs. (3) and (4) exactly as the seed prints them.
double PrintedConvex(double r, double r2, double alpha) {
  return r + r2 - std::sqrt(r * r + r2 * r2 + 2 * r * r2 * std::cos(alpha));
}
double PrintedConcave(double r, double r2, double alpha) {
  return r - r2 + std::sqrt(r * r + r2 * r2 - 2 * r * r2 * std::cos(alpha));
}

TEST(PrincipleErrorTest, MatchesThePrintedFormulas) {
  for (double r : {2.0, 4.0, 10.0}) {
    for (double r2 : {12.0, 50.0, 400.0}) {
      for (double alpha_deg : {0.5, 5.0, 15.0, 40.0}) {
        const double a = alpha_deg * kDeg;
        EXPECT_NEAR(PrincipleErrorConvex(r, r2, a), PrintedConvex(r, r2, a),
                    1e-12 * r2);
        EXPECT_NEAR(PrincipleErrorConcave(r, r2, a), PrintedConcave(r, r2, a),
                    1e-12 * r2);
      }
    }
  }
}

TEST(PrincipleErrorTest, VanishesWithoutTwistAndOrdersConvexBelowConcave) {
  EXPECT_EQ(PrincipleErrorConvex(4, 30, 0), 0.0);
  EXPECT_EQ(PrincipleErrorConcave(4, 30, 0), 0.0);
  // A convex rail turns away from the cutter, a concave one towards it.
  EXPECT_LT(PrincipleErrorConvex(4, 30, 10 * kDeg),
            PrincipleErrorConcave(4, 30, 10 * kDeg));
}

TEST(PrincipleErrorTest, StraightRailLimitIsROneMinusCosAlpha) {
  // In the normal plane the cutter circle (centre R e_n1 from P) crosses a
  // straight line through P whose normal is turned by alpha: depth
  // R - R cos(alpha).
  const double inf = std::numeric_limits<double>::infinity();
  const double a = 11 * kDeg;
  EXPECT_NEAR(PrincipleErrorConvex(4, inf, a), 4 * (1 - std::cos(a)), 1e-15);
  EXPECT_NEAR(PrincipleErrorConcave(4, inf, a), 4 * (1 - std::cos(a)), 1e-15);
  // And the finite formulas approach it without cancellation.
  EXPECT_NEAR(PrincipleErrorConvex(4, 1e12, a), 4 * (1 - std::cos(a)), 1e-12);
  EXPECT_NEAR(PrincipleErrorConcave(4, 1e12, a), 4 * (1 - std::cos(a)), 1e-12);
}

// A configuration that meets the paper's assumptions: the ruling P1P2 is
// vertical (along z, height 20); rail C1 is a straight line through P1 in
// the plane z = 0; rail C2 is a circle of radius R2 in the plane z = 20
// through P2, whose tangent at P2 turns by alpha against C1's. The cutter is
// offset from P1 by R along e_n1 with its axis along the ruling.
struct SeedConfiguration {
  RuledSurface surface;
  Eigen::Vector3d axis_point;
};

SeedConfiguration Build(double r, double r2, double alpha, bool convex) {
  // C1: the x axis through the origin; the cutter side is +y (n1 = +y).
  BSplineCurve c1, c2;
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{-10, 0, 0}, {10, 0, 0}},
                                   "c1", &c1)
                  .ok());
  // C2: circle through P2 = (0, 0, 20) with tangent (cos a, sin a, 0) there
  // and centre on the normal line: convex -> centre away from the cutter
  // (the -y side turned by alpha), concave -> on the cutter's side.
  const Eigen::Vector3d p2(0, 0, 20), t(std::cos(alpha), std::sin(alpha), 0);
  const Eigen::Vector3d n(-std::sin(alpha), std::cos(alpha), 0);
  const Eigen::Vector3d centre =
      convex ? Eigen::Vector3d(p2 - r2 * n) : Eigen::Vector3d(p2 + r2 * n);
  // Over +-10 mm of arc, a clamped cubic whose control points are dense arc
  // points (a fine polygon, 0.05 mm apart): it stays within ~1e-5 mm of the
  // circle, and its radius of curvature near P2 within 1e-3 of R2 (checked
  // below), far inside the 2% the comparison allows.
  std::vector<Eigen::Vector3d> points;
  std::vector<double> knots = {0, 0, 0, 0};
  const int n_ctrl = 401;
  const Eigen::Vector3d radial = (p2 - centre).normalized();
  for (int k = 0; k < n_ctrl; ++k) {
    const double phi = (-10.0 + 20.0 * k / (n_ctrl - 1)) / r2;
    points.push_back(centre +
                     r2 * (std::cos(phi) * radial + std::sin(phi) * t));
  }
  for (int k = 1; k < n_ctrl - 3; ++k) {
    knots.push_back(static_cast<double>(k) / (n_ctrl - 3));
  }
  for (int k = 0; k < 4; ++k) knots.push_back(1.0);
  EXPECT_TRUE(BSplineCurve::Create(3, knots, points, "c2", &c2).ok());
  // r_u x r_v = x cross z = -y at P1, so the cutter's +y side is "negative".
  return {RuledSurface("config", c1, c2, CutterSide::kNegative), {0, r, 0}};
}

// Deepest penetration (mm, >= 0) of the cutter, axis through axis_point
// along z, into C2 within +-4 mm of P2, scanning the rail finely.
double NumericError(const SeedConfiguration& s, const Cutter& cutter) {
  double deepest = 0.0;
  const Eigen::Vector3d tip(s.axis_point.x(), s.axis_point.y(), -5);
  for (int k = 0; k <= 20000; ++k) {
    const Eigen::Vector3d q = s.surface.rail(1).Point(0.3 + 0.4 * k / 20000.0);
    deepest = std::min(deepest, SignedDistanceToCutter<double>(
                                    cutter, q, tip, Eigen::Vector3d::UnitZ()));
  }
  return -deepest;
}

TEST(PrincipleErrorTest, MatchesNumericDeviationOfTheSeedConfiguration) {
  Cutter cutter;
  cutter.radius_mm = 4.0;
  cutter.flute_length_mm = 40.0;
  for (double r2 : {20.0, 50.0}) {
    for (double alpha_deg : {5.0, 15.0}) {
      for (bool convex : {true, false}) {
        SCOPED_TRACE(::testing::Message()
                     << "R2 " << r2 << " alpha " << alpha_deg
                     << (convex ? " convex" : " concave"));
        const SeedConfiguration s =
            Build(cutter.radius_mm, r2, alpha_deg * kDeg, convex);
        // The configuration is what the formula assumes: the surface's own
        // normals at the ruling's ends differ by alpha, and the rail's
        // curvature radius at P2 is R2.
        const double angle = std::acos(std::clamp(
            s.surface.Normal(0.5, 0).dot(s.surface.Normal(0.5, 1)), -1.0, 1.0));
        ASSERT_NEAR(angle / kDeg, alpha_deg, 0.05);
        ASSERT_NEAR(s.surface.RailCurvatureRadius(1, 0.5), r2, 1e-3 * r2);
        const double expected =
            convex ? PrincipleErrorConvex(4, r2, alpha_deg * kDeg)
                   : PrincipleErrorConcave(4, r2, alpha_deg * kDeg);
        EXPECT_GT(expected, 1e-3);
        EXPECT_NEAR(NumericError(s, cutter), expected, 0.02 * expected);
      }
    }
  }
}

// The formula predicts the swept-cutter evaluator on a real path: a
// hyperbolic paraboloid (straight rails, R2 = infinity) cut by a dense
// single-point-offset path. Every pose is tangent along its ruling, so the
// overcut is the principle error, deepest at v = 1 where the twist alpha(u)
// between the normals at the ruling's ends is largest (u = 0.5 here, by
// symmetry).
TEST(PrincipleErrorTest, PredictsTheSweptDeviationOfASpoPathOnAHypar) {
  BSplineCurve c1, c2;
  ASSERT_TRUE(
      BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {60, 0, 0}}, "c1", &c1)
          .ok());
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 6, 30}, {60, -6, 30}},
                                   "c2", &c2)
                  .ok());
  const RuledSurface hypar("hypar", c1, c2, CutterSide::kPositive);
  const Cutter cutter{4.0, 45.0, 0.0};
  ToolPath path;
  for (int i = 0; i <= 400; ++i) {
    const double u = i / 400.0;
    ToolPose pose;
    pose.p_w_tip = hypar.Point(u, 0) + cutter.radius_mm * hypar.Normal(u, 0);
    pose.a_w = (hypar.Point(u, 1) - hypar.Point(u, 0)).normalized();
    path.poses.push_back(pose);
  }
  DeviationOptions options;
  options.samples_u = 41;
  options.samples_v = 11;
  options.u_min = 0.25;  // away from the path's ends, where the poses
  options.u_max = 0.75;  // that would cut deepest are missing
  DeviationReport report;
  ASSERT_TRUE(
      EvaluateDeviation(hypar, cutter, path, nullptr, options, &report).ok());

  double alpha_max = 0.0;
  for (double u : report.u) {
    alpha_max = std::max(
        alpha_max, std::acos(std::clamp(
                       hypar.Normal(u, 0).dot(hypar.Normal(u, 1)), -1.0, 1.0)));
  }
  EXPECT_NEAR(alpha_max / kDeg, std::atan(0.2) / kDeg, 1e-9);
  ASSERT_TRUE(std::isinf(hypar.RailCurvatureRadius(1, 0.5)));
  const double expected =
      PrincipleErrorConvex(4, hypar.RailCurvatureRadius(1, 0.5), alpha_max);
  EXPECT_NEAR(report.max_overcut_mm, expected, 0.02 * expected);
  EXPECT_NEAR(report.overcut_u, 0.5, 0.05);
  EXPECT_EQ(report.overcut_v, 1.0);
  EXPECT_LT(report.max_undercut_mm, 1e-6);
}

}  // namespace
}  // namespace tpopt
