// Even stations (solver/smooth/even_stations.h) against closed forms: a
// straight flank path along a plane strip whose A turns linearly with the
// tip's travel, spaced unevenly, comes back at equal steps with A at its
// linear value there; the stretch's ends, lead poses beyond the surface's
// ends and the poses around a rapid stay where they are (the strip neither
// curves nor twists, so every move errs alike at equal steps); and on a
// strip whose ruling turns at a constant rate in its second half only, the
// steps there are shorter by the square root of twice the error density;
// split moves add stations between the program's poses at the same steps.
// The joint bow is zero where the rotaries stand still, the middle of the
// move's brute-force farthest point off the chord where they turn, four
// times as large for a move twice as long, and blind to the leads.
#include "solver/smooth/even_stations.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "tests/analytic_surfaces.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kLengthMm = 100.0, kRadiusMm = 4.0;
// A over the strip, rad per mm of x.
constexpr double kASlope = 0.002;

// The plane strip x in [0, 100], z in [0, 30] at y = 0; the cutter on +y.
RuledSurface Strip() {
  BSplineCurve rail0, rail1;
  CHECK(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {kLengthMm, 0, 0}}, "rail 0", &rail0)
            .ok());
  CHECK(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 30}, {kLengthMm, 0, 30}}, "rail 1", &rail1)
            .ok());
  return RuledSurface("strip", rail0, rail1, CutterSide::kPositive);
}

// The pose with its tip at x on the strip's floor line offset by R, and
// A = kASlope x, C = 0 (a = (0, sin A, cos A)).
ToolPose PoseAt(double x_mm) {
  ToolPose pose;
  pose.p_w_tip = Eigen::Vector3d(x_mm, kRadiusMm, 0);
  const double a = kASlope * x_mm;
  pose.a_w = Eigen::Vector3d(0, std::sin(a), std::cos(a));
  pose.feed_mm_per_min = 1000;
  return pose;
}

class EvenStationsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(
        ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &machine_).ok());
  }
  RuledSurface surface_ = Strip();
  Machine machine_;
};

TEST_F(EvenStationsTest, UnevenPosesComeBackAtEqualStepsOnTheInputsMotion) {
  for (const Interpolation model : {Interpolation::kTcp, Interpolation::kJoint}) {
    SCOPED_TRACE(InterpolationName(model));
    ToolPath path;
    // A lead-in beyond x = 0, then uneven poses with a micrometre pair.
    for (double x : {-4.0, -2.0, 0.0, 1.0, 5.0, 5.001, 20.0, 50.0, 51.0, 100.0}) {
      path.poses.push_back(PoseAt(x));
    }
    path.poses[0].rapid = true;
    ToolPath even;
    ASSERT_TRUE(EvenStations(path, surface_, machine_, model, 1, &even).ok());
    ASSERT_EQ(even.poses.size(), path.poses.size());
    // The lead-in (beyond the end) and the stretch's ends keep their place.
    for (size_t i : {0u, 1u, 2u, 9u}) {
      EXPECT_EQ(even.poses[i].p_w_tip, path.poses[i].p_w_tip) << i;
      EXPECT_EQ(even.poses[i].a_w, path.poses[i].a_w) << i;
    }
    // Poses 2..9 span x 0..100 in 7 moves: the interior at 100 k / 7. Under
    // TCP the tip is on the line exactly and A linear in it; the joint
    // model moves the tip off the line by the rotaries' turn only.
    const double tip_mm = model == Interpolation::kTcp ? 1e-9 : 0.05;
    for (size_t k = 1; k < 7; ++k) {
      const ToolPose expected = PoseAt(kLengthMm * k / 7.0);
      const ToolPose& got = even.poses[2 + k];
      EXPECT_NEAR((got.p_w_tip - expected.p_w_tip).norm(), 0, tip_mm) << k;
      EXPECT_NEAR(std::acos(std::min(1.0, got.a_w.dot(expected.a_w))), 0, 1e-7) << k;
      EXPECT_EQ(got.feed_mm_per_min, path.poses[2 + k].feed_mm_per_min);
    }
  }
}

TEST_F(EvenStationsTest, ARapidOrAToolChangeEndsAStretch) {
  ToolPath path;
  for (double x : {0.0, 2.0, 3.0, 40.0, 41.0, 60.0, 90.0, 100.0}) path.poses.push_back(PoseAt(x));
  path.poses[3].rapid = true;  // two stretches: 0..2 and 3..7
  for (size_t i = 5; i < path.poses.size(); ++i) path.poses[i].tool = 1;  // 3..4, 5..7
  ToolPath even;
  ASSERT_TRUE(EvenStations(path, surface_, machine_, Interpolation::kTcp, 1, &even).ok());
  // 0..2: pose 1 at x 1.5; 3..4: nothing inside; 5..7: pose 6 at x 80.
  const std::vector<double> x = {0, 1.5, 3, 40, 41, 60, 80, 100};
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(even.poses[i].p_w_tip.x(), x[i], 1e-9) << i;
  }
}

// The ruling turns about the rail (x) by theta(t) = 0 for t < 1/2 and
// k (t - 1/2)^2 beyond, so e'' = 0 in the first half and constant, |e''| =
// 2k / 100^2 per mm^2, in the second. Density M = 30 |e''| / 8 there, 0 before;
// floored at its mean over the stretch (M / 2 with the poses spread
// evenly), the weights are sqrt(M / 2) and sqrt(M): steps in the first half
// sqrt(2) times those in the second.
TEST_F(EvenStationsTest, StepsShortenWhereTheRulingTurns) {
  constexpr double k = 0.8;  // rad over the half: 0.2 rad end to end
  const RuledSurface turning = testing::RuledThrough(
      "turning", 40, CutterSide::kPositive, [&](double t) {
        const double theta = t < 0.5 ? 0.0 : k * (t - 0.5) * (t - 0.5);
        return testing::Ruling{Eigen::Vector3d(kLengthMm * t, 0, 0),
                               Eigen::Vector3d(0, -std::sin(theta), std::cos(theta)), 30.0};
      });
  ToolPath path;
  constexpr int kPoses = 101;
  for (int i = 0; i < kPoses; ++i) path.poses.push_back(PoseAt(kLengthMm * i / (kPoses - 1)));
  ToolPath even;
  ASSERT_TRUE(EvenStations(path, turning, machine_, Interpolation::kTcp, 1, &even).ok());
  // Mean step over x in [10, 40] and in [60, 90], away from the blend at 50.
  const auto mean_step = [&](double from, double to) {
    double sum = 0;
    int count = 0;
    for (int i = 1; i < kPoses; ++i) {
      const double x = even.poses[i].p_w_tip.x();
      if (x < from || x > to) continue;
      sum += x - even.poses[i - 1].p_w_tip.x();
      ++count;
    }
    return sum / count;
  };
  EXPECT_NEAR(mean_step(10, 40) / mean_step(60, 90), std::sqrt(2.0), 0.1);
}

// Split in three, the stretch 0..100 of 7 moves gets 21, at 100 k / 21 on
// the line: every third is the unsplit station with the program's pose
// (its source line), those between new poses of the move into it.
TEST_F(EvenStationsTest, SplitMovesAddEqualStepsBetweenTheProgramsPoses) {
  ToolPath path;
  for (double x : {-4.0, -2.0, 0.0, 1.0, 5.0, 5.001, 20.0, 50.0, 51.0, 100.0}) {
    path.poses.push_back(PoseAt(x));
    path.poses.back().source_line = static_cast<int>(path.poses.size());
    path.poses.back().feed_mm_per_min = 100.0 * path.poses.size();
  }
  path.poses[0].rapid = true;
  ToolPath split;
  ASSERT_TRUE(EvenStations(path, surface_, machine_, Interpolation::kTcp, 3, &split).ok());
  ASSERT_EQ(split.poses.size(), 2u + 22u);
  // The lead-in keeps its two poses and its move; the stretch starts at 2.
  for (size_t i : {0u, 1u, 2u}) EXPECT_EQ(split.poses[i].p_w_tip, path.poses[i].p_w_tip) << i;
  for (size_t k = 1; k <= 21; ++k) {
    const ToolPose& got = split.poses[2 + k];
    const ToolPose expected = PoseAt(kLengthMm * k / 21.0);
    EXPECT_NEAR((got.p_w_tip - expected.p_w_tip).norm(), 0, 1e-9) << k;
    EXPECT_NEAR(std::acos(std::min(1.0, got.a_w.dot(expected.a_w))), 0, 1e-7) << k;
    const size_t program_pose = 2 + (k + 2) / 3;
    EXPECT_EQ(got.source_line, k % 3 == 0 ? path.poses[program_pose].source_line : 0) << k;
    EXPECT_EQ(got.feed_mm_per_min, path.poses[program_pose].feed_mm_per_min) << k;
  }
  ToolPath refused;
  EXPECT_FALSE(EvenStations(path, surface_, machine_, Interpolation::kTcp, 0, &refused).ok());
}

// The farthest the joint-linear tip of the move from pose 0 to pose 1 of
// `path` strays from the chord, over 1000 points of the move.
double BruteForceBowMm(const ToolPath& path, const Machine& machine) {
  std::vector<JointVector> joints;
  CHECK(machine.AssignJoints(path, &joints).ok());
  const Eigen::Vector3d& p0 = path.poses[0].p_w_tip;
  const Eigen::Vector3d& p1 = path.poses[1].p_w_tip;
  double farthest = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    Eigen::Vector3d tip, axis;
    InterpolateMove<double>(machine.kinematics, Interpolation::kJoint, joints[0], joints[1], p0, p1,
                            k / 1000.0, &tip, &axis);
    const Eigen::Vector3d along = (p1 - p0).normalized();
    const Eigen::Vector3d off = tip - p0;
    farthest = std::max(farthest, (off - off.dot(along) * along).norm());
  }
  return farthest;
}

TEST_F(EvenStationsTest, TheJointBowIsTheMovesFarthestPointOffItsLine) {
  // Rotaries still: the joint move is the straight line.
  ToolPath still;
  for (double x : {10.0, 60.0}) {
    still.poses.push_back(PoseAt(x));
    still.poses.back().a_w = PoseAt(10).a_w;
  }
  double bow_mm = -1;
  ASSERT_TRUE(LargestJointBowMm(still, surface_, machine_, &bow_mm).ok());
  EXPECT_NEAR(bow_mm, 0.0, 1e-9);
  // A turning 0.002 rad a millimetre: the bow is the brute-force farthest
  // point, and a move twice as long (twice the turn) bows four times as far.
  std::vector<double> bows;
  for (double length_mm : {20.0, 40.0}) {
    ToolPath move;
    for (double x : {30.0, 30.0 + length_mm}) move.poses.push_back(PoseAt(x));
    ASSERT_TRUE(LargestJointBowMm(move, surface_, machine_, &bow_mm).ok());
    const double brute_mm = BruteForceBowMm(move, machine_);
    EXPECT_GT(brute_mm, 5e-4) << length_mm;
    EXPECT_NEAR(bow_mm, brute_mm, 0.02 * brute_mm) << length_mm;
    bows.push_back(bow_mm);
  }
  EXPECT_NEAR(bows[1] / bows[0], 4.0, 0.2);
  // A lead-in beyond x = 0 that turns A by 0.5 rad is not a cutting
  // stretch's move: the bow is the stretch's own.
  ToolPath led;
  for (double x : {-6.0, 30.0, 50.0}) led.poses.push_back(PoseAt(x));
  led.poses[0].a_w = Eigen::Vector3d(0, std::sin(0.5), std::cos(0.5));
  ASSERT_TRUE(LargestJointBowMm(led, surface_, machine_, &bow_mm).ok());
  EXPECT_NEAR(bow_mm, bows[0], 1e-9);
}

}  // namespace
}  // namespace tpopt
