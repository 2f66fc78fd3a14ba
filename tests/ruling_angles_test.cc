#include "solver/smooth/ruling_angles.h"

#include <cmath>

#include <gtest/gtest.h>

#include "model/machine/machine.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A plane strip along X whose rulings all lean `lean_deg` from +Z towards
// +Y: axis (0, sin, cos), so A = lean and C = atan2(0, sin) = 0 on branch 0.
RuledSurface LeaningStrip(double lean_deg) {
  const Eigen::Vector3d up(0, 30 * std::sin(lean_deg * kDeg), 30 * std::cos(lean_deg * kDeg));
  const Eigen::Vector3d a(0, 0, 0), b(50, 0, 0);
  BSplineCurve r0, r1;
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {a, b}, "r0", &r0).ok());
  EXPECT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {a + up, b + up}, "r1", &r1).ok());
  return RuledSurface("strip", r0, r1, CutterSide::kPositive);
}

TEST(RulingAnglesTest, TheRulingsAnglesOnTheStartsBranchAndWinding) {
  const RuledSurface strip = LeaningStrip(30);
  const std::vector<Eigen::Vector2d> start = {
      {31 * kDeg, 0.1},                // branch 0
      {29 * kDeg, 2 * M_PI - 0.05},    // branch 0, a turn of C on
      {-30.5 * kDeg, M_PI + 0.02},     // branch 1
  };
  const auto angles = RulingAngles(strip, {0.2, 0.5, 0.8}, {false, false, false}, start, 12, true);
  ASSERT_EQ(angles.size(), 3u);
  for (const RulingReference& a : angles) ASSERT_TRUE(a.a.has_value() && a.c.has_value());
  EXPECT_NEAR(*angles[0].a, 30 * kDeg, 1e-12);
  EXPECT_NEAR(*angles[0].c, 0.0, 1e-12);
  EXPECT_NEAR(*angles[1].a, 30 * kDeg, 1e-12);
  EXPECT_NEAR(*angles[1].c, 2 * M_PI, 1e-12);
  EXPECT_NEAR(*angles[2].a, -30 * kDeg, 1e-12);
  EXPECT_NEAR(*angles[2].c, M_PI, 1e-12);
  // Each is the ruling's direction itself.
  for (const RulingReference& a : angles) {
    EXPECT_NEAR((AnglesToAxis(*a.a, *a.c) - Eigen::Vector3d(0, 0.5, std::sqrt(0.75))).norm(), 0.0,
                1e-12);
  }
}

TEST(RulingAnglesTest, NoneBeyondTheEndsOrOutsideTheCone) {
  const RuledSurface strip = LeaningStrip(30);
  const std::vector<Eigen::Vector2d> start = {{30 * kDeg, 0.0}, {30 * kDeg, 0.0}, {45 * kDeg, 0.0}};
  const auto angles = RulingAngles(strip, {0.0, 0.5, 0.5}, {true, false, false}, start, 12, true);
  EXPECT_FALSE(angles[0].a || angles[0].c);  // a lead pose beyond the ends
  EXPECT_TRUE(angles[1].a && angles[1].c);
  EXPECT_FALSE(angles[2].a || angles[2].c);  // its start axis 15 deg from the ruling
  // The ruling's sense does not matter: a start axis pointing down the
  // ruling gets the reversed ruling's angles.
  const auto down = RulingAngles(strip, {0.5}, {false}, {{150 * kDeg, M_PI}}, 12, true);
  ASSERT_TRUE(down[0].a.has_value());
  EXPECT_NEAR(*down[0].a, 150 * kDeg, 1e-12);
}

TEST(RulingAnglesTest, NearThePoleAOnlyWhereAskedAndClearOfThePole) {
  // A ruling 10 deg from the pole: C would turn as 1 / sin A and has no
  // reference; A has one when asked for, on either branch, where the start
  // axis lies less than half those 10 deg from the ruling (here 3.4 deg:
  // 0.5 deg nearer the pole and 20 deg of C round it).
  const RuledSurface steep = LeaningStrip(kRulingAnglesPoleDeg - 5);
  const std::vector<Eigen::Vector2d> start = {{9.5 * kDeg, 20 * kDeg},
                                              {-9.5 * kDeg, M_PI + 20 * kDeg}};
  for (const RulingReference& r : RulingAngles(steep, {0.5, 0.5}, {false, false}, start, 12, false)) {
    EXPECT_FALSE(r.a || r.c);
  }
  const auto near = RulingAngles(steep, {0.5, 0.5}, {false, false}, start, 12, true);
  EXPECT_FALSE(near[0].c || near[1].c);
  ASSERT_TRUE(near[0].a && near[1].a);
  EXPECT_NEAR(*near[0].a, 10 * kDeg, 1e-12);
  EXPECT_NEAR(*near[1].a, -10 * kDeg, 1e-12);
  // A start axis 6 deg from the ruling (16 deg from the pole) is more than
  // half the ruling's 10 deg from it: its A would not follow the ruling's.
  const auto far = RulingAngles(steep, {0.5}, {false}, {{16 * kDeg, 0.0}}, 12, true);
  EXPECT_FALSE(far[0].a || far[0].c);
}

}  // namespace
}  // namespace tpopt
