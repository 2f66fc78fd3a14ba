#include "model/machine/interpolation.h"

#include <cmath>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The kinematics of data/machines/linuxcnc_xyzac_trt_sim.json.
Machine SimMachine() {
  Machine m;
  m.kinematics.y_offset_mm = 20.0;
  m.kinematics.z_offset_mm = 10.0;
  return m;
}

TEST(InterpolationTest, NamesRoundTrip) {
  for (Interpolation i : {Interpolation::kTcp, Interpolation::kJoint}) {
    Interpolation parsed = i == Interpolation::kTcp ? Interpolation::kJoint : Interpolation::kTcp;
    ASSERT_TRUE(ParseInterpolation(InterpolationName(i), &parsed));
    EXPECT_EQ(parsed, i);
  }
  Interpolation kept = Interpolation::kTcp;
  EXPECT_FALSE(ParseInterpolation("linear", &kept));
  EXPECT_EQ(kept, Interpolation::kTcp);
}

// At the pole (A = 0) the table turns by theta about C while the tip stays
// at p in W. In W the joint-linear tip cuts the chord of the circle of
// radius rho = |p_xy| about the C axis: at mid-move it lies at rho
// cos(theta / 2) in p's direction, a bow of rho (1 - cos(theta / 2)); the
// TCP tip stays at p. Both axes are +Z.
TEST(InterpolationTest, AtThePoleJointModeBowsByTheChordSagitta) {
  const Machine m = SimMachine();
  const Eigen::Vector3d p(30, 10, 5);
  const double theta = 60 * kDeg;
  const JointVector j0 = m.ToJoints(p, 0.0, 0.0), j1 = m.ToJoints(p, 0.0, theta);
  Eigen::Vector3d tip, axis;
  InterpolateMove<double>(m.kinematics, Interpolation::kJoint, j0, j1, p, p, 0.5, &tip, &axis);
  const double rho = std::hypot(p.x(), p.y());
  EXPECT_NEAR(std::hypot(tip.x(), tip.y()), rho * std::cos(theta / 2), 1e-9);
  EXPECT_NEAR(tip.x() * p.y() - tip.y() * p.x(), 0.0, 1e-9);  // same direction
  EXPECT_NEAR(tip.z(), p.z(), 1e-9);
  EXPECT_NEAR((axis - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  InterpolateMove<double>(m.kinematics, Interpolation::kTcp, j0, j1, p, p, 0.5, &tip, &axis);
  EXPECT_NEAR((tip - p).norm(), 0.0, 1e-12);
}

// Near the pole (A = 1.7 deg) a C swing of 90 deg: the TCP tip stays on the
// chord of the two programmed tips at every s with the axis of the linear
// A, C; under a fixed tip the joint tip leaves it by the sagitta above to
// within the O(A) change of the radius (a few percent here).
TEST(InterpolationTest, NearThePoleTcpFollowsTheChord) {
  const Machine m = SimMachine();
  const double a = 1.7 * kDeg;
  const Eigen::Vector3d p0(25, -8, 4), p1(26, -7, 4.2);
  const JointVector j0 = m.ToJoints(p0, a, 0.0), j1 = m.ToJoints(p1, a, 90 * kDeg);
  for (double s : {0.25, 0.5, 0.75}) {
    Eigen::Vector3d tip, axis;
    InterpolateMove<double>(m.kinematics, Interpolation::kTcp, j0, j1, p0, p1, s, &tip, &axis);
    EXPECT_NEAR((tip - ((1 - s) * p0 + s * p1)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((axis - AnglesToAxis(a, s * 90 * kDeg)).norm(), 0.0, 1e-12);
  }
  // The table turning under a fixed tip p0.
  const JointVector j2 = m.ToJoints(p0, a, 90 * kDeg);
  Eigen::Vector3d tip, axis;
  InterpolateMove<double>(m.kinematics, Interpolation::kJoint, j0, j2, p0, p0, 0.5, &tip, &axis);
  const double sagitta = std::hypot(p0.x(), p0.y()) * (1 - std::cos(45 * kDeg));
  EXPECT_NEAR((tip - p0).norm(), sagitta, 0.05 * sagitta);
  // The joint tip is where the machine puts the mean joints.
  Eigen::Vector3d fk_tip, fk_axis;
  m.ToWorkpiece(0.5 * (j0 + j2), &fk_tip, &fk_axis);
  EXPECT_NEAR((tip - fk_tip).norm(), 0.0, 1e-12);
  EXPECT_NEAR((axis - fk_axis).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace tpopt
