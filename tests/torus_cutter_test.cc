// The torus cutter's distance and contact placement against its geometry.
#include "model/cutter/torus_cutter.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

const TorusCutter kCutter{8.0, 2.0};  // R0 = 6

TEST(TorusCutterTest, DistanceToKnownPoints) {
  const Eigen::Vector3d tip(1, 2, 3), axis = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Vector3d side = Eigen::Vector3d(1, -1, 0).normalized();  // normal to the axis
  // Below the tip on the axis: the end face is flat there.
  EXPECT_NEAR(SignedDistanceToTorus(kCutter, tip - 0.7 * axis, tip, axis), 0.7, 1e-12);
  // Level with the centre circle, beyond the flank.
  EXPECT_NEAR(SignedDistanceToTorus(kCutter, tip + 2 * axis + 9.5 * side, tip, axis), 1.5, 1e-12);
  // High up beside the flank: the cylinder of radius R.
  EXPECT_NEAR(SignedDistanceToTorus(kCutter, tip + 30 * axis + 8.25 * side, tip, axis), 0.25,
              1e-12);
  // Off the corner, along its normal at tube angle psi (below the circle).
  for (double psi : {-0.2, -0.8, -1.4}) {
    const Eigen::Vector3d normal = std::cos(psi) * side + std::sin(psi) * axis;
    const Eigen::Vector3d on = tip + 2 * axis + 6 * side + 2 * normal;
    EXPECT_NEAR(SignedDistanceToTorus(kCutter, on, tip, axis), 0.0, 1e-12);
    EXPECT_NEAR(SignedDistanceToTorus(kCutter, on + 0.3 * normal, tip, axis), 0.3, 1e-12);
    EXPECT_NEAR(SignedDistanceToTorus(kCutter, on - 0.3 * normal, tip, axis), -0.3, 1e-12);
  }
}

TEST(TorusCutterTest, ContactPlacementTouchesWithTheRightNormal) {
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d n = Eigen::Vector3d(gauss(random), gauss(random), gauss(random)).normalized();
    Eigen::Vector3d other = Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
    other = (other - other.dot(n) * n).normalized();
    const double lead = 0.02 + 1.3 * std::abs(std::sin(trial));
    const Eigen::Vector3d axis = std::cos(lead) * n + std::sin(lead) * other;
    const Eigen::Vector3d contact(gauss(random), gauss(random), gauss(random));
    const Eigen::Vector3d tip = TipForContact(kCutter, contact, n, axis);
    EXPECT_NEAR(SignedDistanceToTorus(kCutter, contact, tip, axis), 0.0, 1e-12);
    // The distance grows at unit rate along +n and falls along -n: the
    // cutter's outward normal at the contact is -n.
    const double h = 1e-6;
    const auto d = [&](const Eigen::Vector3d& q) { return SignedDistanceToTorus(kCutter, q, tip, axis); };
    EXPECT_NEAR((d(contact - h * n) - d(contact + h * n)) / (2 * h), 1.0, 1e-6);
    EXPECT_NEAR((d(contact + h * other.cross(n)) - d(contact - h * other.cross(n))) / (2 * h), 0.0,
                1e-6);
  }
}

TEST(TorusCutterTest, AxisAlongTheNormalPutsTheEndFaceOnTheContact) {
  const Eigen::Vector3d contact(3, 4, 5), n = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d tip = TipForContact(kCutter, contact, n, n);
  EXPECT_LT((tip - contact).norm(), 1e-15);
  EXPECT_NEAR(SignedDistanceToTorus(kCutter, contact - 0.1 * n, tip, n), 0.1, 1e-12);
}

TEST(TorusCutterTest, EffectiveRadiusLimits) {
  // At 90 deg the contact is on the outer equator, whose parallel circle
  // is the flank: R_eff = R. As the lead falls the end face flattens out.
  EXPECT_NEAR(EffectiveRadiusAtLead(kCutter, M_PI / 2), 8.0, 1e-12);
  EXPECT_NEAR(EffectiveRadiusAtLead(kCutter, M_PI / 6), 2 + 12, 1e-12);
  std::string why;
  EXPECT_FALSE((TorusCutter{4.0, 5.0}).IsValid(&why));
  EXPECT_NE(why.find("r = 5"), std::string::npos) << why;
}

}  // namespace
}  // namespace tpopt
