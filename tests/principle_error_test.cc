#include "model/principle_error.h"

#include <gtest/gtest.h>

#include "model/cutter.h"
#include "model/ruled_surface.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

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
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{-10, 0, 0}, {10, 0, 0}}, "c1", &c1).ok());
  // C2: circle through P2 = (0, 0, 20) with tangent (cos a, sin a, 0) there
  // and centre on the normal side: convex -> centre away from the cutter
  // (-y side turned by alpha), concave -> on the cutter's side.
  const Eigen::Vector3d p2(0, 0, 20), t(std::cos(alpha), std::sin(alpha), 0);
  const Eigen::Vector3d n(-std::sin(alpha), std::cos(alpha), 0);  // +y turned by alpha
  const Eigen::Vector3d centre = convex ? Eigen::Vector3d(p2 - r2 * n) : Eigen::Vector3d(p2 + r2 * n);
  // Interpolate the arc over +-10 mm of arc length densely with a clamped
  // cubic whose control points are the arc points (a fine polygon): the
  // radius of curvature stays within 1e-4 of R2 near P2.
  std::vector<Eigen::Vector3d> points;
  std::vector<double> knots = {0, 0, 0, 0};
  const int n_ctrl = 401;
  for (int k = 0; k < n_ctrl; ++k) {
    const double s = -10.0 + 20.0 * k / (n_ctrl - 1);  // arc length
    const double phi = s / r2;
    const Eigen::Vector3d radial = (p2 - centre).normalized();
    points.push_back(centre + r2 * (std::cos(phi) * radial + std::sin(phi) * t));
  }
  for (int k = 1; k < n_ctrl - 3; ++k) knots.push_back(static_cast<double>(k) / (n_ctrl - 3));
  for (int k = 0; k < 4; ++k) knots.push_back(1.0);
  EXPECT_TRUE(BSplineCurve::Create(3, knots, points, "c2", &c2).ok());
  // r_u x r_v = x x z = -y at P1, so the cutter's +y side is "negative".
  return {RuledSurface("config", c1, c2, CutterSide::kNegative), {0, r, 0}};
}

// Deepest penetration of the cutter (axis through axis_point along z) into
// C2 near P2, scanning the rail finely.
double NumericError(const SeedConfiguration& s, const Cutter& cutter) {
  double deepest = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const Eigen::Vector3d q = s.surface.rail(1).Point(0.3 + 0.4 * k / 20000.0);
    const double d = SignedDistanceToCutter<double>(cutter, q, {s.axis_point.x(), s.axis_point.y(), -5},
                                                    Eigen::Vector3d::UnitZ());
    deepest = std::min(deepest, d);
  }
  return -deepest;
}

TEST(PrincipleErrorTest, FormulasVanishWithoutTwist) {
  EXPECT_NEAR(PrincipleErrorConvex(4, 30, 0), 0.0, 1e-12);
  EXPECT_NEAR(PrincipleErrorConcave(4, 30, 0), 0.0, 1e-12);
}

TEST(PrincipleErrorTest, MatchesNumericDeviationOfTheSeedConfiguration) {
  Cutter cutter;
  cutter.radius_mm = 4.0;
  cutter.flute_length_mm = 40.0;
  for (double r2 : {20.0, 50.0}) {
    for (double alpha_deg : {5.0, 15.0}) {
      for (bool convex : {true, false}) {
        const SeedConfiguration s = Build(cutter.radius_mm, r2, alpha_deg * kDeg, convex);
        // The surface's own normals at the ruling ends differ by alpha.
        const double angle = std::acos(std::clamp(
            s.surface.Normal(0.5, 0).dot(s.surface.Normal(0.5, 1)), -1.0, 1.0));
        ASSERT_NEAR(angle / kDeg, alpha_deg, 0.05);
        const double expected = convex ? PrincipleErrorConvex(4, r2, alpha_deg * kDeg)
                                       : PrincipleErrorConcave(4, r2, alpha_deg * kDeg);
        const double numeric = NumericError(s, cutter);
        EXPECT_NEAR(numeric, expected, 0.02 * expected)
            << "R2 " << r2 << " alpha " << alpha_deg << (convex ? " convex" : " concave");
      }
    }
  }
}

}  // namespace
}  // namespace tpopt
