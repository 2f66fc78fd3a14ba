#include "model/machine/planner_time.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/machine/axis_metrics.h"

namespace tpopt {
namespace {

constexpr double kAccel = 300.0;  // mm/s^2 on each linear axis
constexpr double kTangential = 0.5 * kAccel;

// Straight moves along X from 0 through the given ends, axis vertical, each
// with its feed in mm/min; the first pose is where the run starts.
ToolPath LineAlongX(const std::vector<double>& ends_mm,
                    const std::vector<double>& feeds) {
  ToolPath path;
  ToolPose start;
  start.p_w_tip = Eigen::Vector3d::Zero();
  start.a_w = Eigen::Vector3d::UnitZ();
  path.poses.push_back(start);
  for (size_t k = 0; k < ends_mm.size(); ++k) {
    ToolPose p = start;
    p.p_w_tip.x() = ends_mm[k];
    p.feed_mm_per_min = feeds[k];
    path.poses.push_back(p);
  }
  return path;
}

Machine LinearAccelMachine() {
  Machine m;
  for (int a : {kX, kY, kZ}) m.limits[a].max_acceleration = kAccel;
  return m;
}

PlannerTime Predict(const Machine& m, const ToolPath& path) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(m.AssignJoints(path, &joints).ok());
  return PredictPlannerTime(m, path, joints, PlannerOptions());
}

// Brute force: the fastest motion along a line that starts and ends at rest,
// keeps each piece's speed limit and accelerates at most `a`, has at every x
// the speed v(x) = min over pieces j of sqrt(v_j^2 + 2 a dist(x, piece j)),
// and from rest at both ends; its time is the integral of dx / v(x), taken
// over x = L (1 - cos theta) / 2 so that the 1 / sqrt(x) at rest is smooth.
double BruteForceTime(const std::vector<double>& ends_mm,
                      const std::vector<double>& speeds, double a) {
  const double length = ends_mm.back();
  const int steps = 200000;
  const double dtheta = M_PI / steps;
  double t = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double theta = (s + 0.5) * dtheta;
    const double x = 0.5 * length * (1 - std::cos(theta));
    const double dx = 0.5 * length * std::sin(theta) * dtheta;
    double v = std::sqrt(2 * a * std::min(x, length - x));
    double from = 0.0;
    for (size_t j = 0; j < ends_mm.size(); ++j) {
      const double dist =
          x < from ? from - x : (x > ends_mm[j] ? x - ends_mm[j] : 0.0);
      v = std::min(v, std::sqrt(speeds[j] * speeds[j] + 2 * a * dist));
      from = ends_mm[j];
    }
    t += dx / v;
  }
  return t;
}

TEST(PlannerTimeTest, TwoFeedsOnALineCostTheirRampsInClosedForm) {
  // 10 mm at 20 mm/s, then 10 mm at 5 mm/s: the ramp between them takes
  // dv / a_t = 0.1 s at a_t = 150 mm/s^2 and costs dv^2 / (2 a_t v_high).
  const double v1 = 20.0, v2 = 5.0;
  const ToolPath path = LineAlongX({10.0, 20.0}, {60 * v1, 60 * v2});
  const PlannerTime t = Predict(LinearAccelMachine(), path);
  const double ramps = v1 / (2 * kTangential) +
                       (v1 - v2) * (v1 - v2) / (2 * kTangential * v1) +
                       v2 / (2 * kTangential);
  EXPECT_NEAR(t.ramp_time_s, ramps, 1e-12);
  EXPECT_NEAR(t.time_s, 10 / v1 + 10 / v2 + ramps, 1e-12);
  EXPECT_NEAR(t.time_s, BruteForceTime({10.0, 20.0}, {v1, v2}, kTangential),
              1e-6);
  EXPECT_EQ(t.capped_moves, 0);
  // The plain model has no ramps: the difference is exactly theirs.
  std::vector<JointVector> joints;
  ASSERT_TRUE(LinearAccelMachine().AssignJoints(path, &joints).ok());
  const MotionReport plain =
      EvaluateMotion(LinearAccelMachine(), path, joints, MotionOptions());
  EXPECT_NEAR(plain.machining_time_s, 10 / v1 + 10 / v2, 1e-12);
  EXPECT_NEAR(plain.planner_time_s, t.time_s, 1e-12);
}

TEST(PlannerTimeTest, ShortMovesRunAtTheirTriangleSpeed) {
  // 40 moves of 0.2 mm asked for 30 mm/s: none can reach more than
  // sqrt(a_t L) = sqrt(30) mm/s and leave again within its length.
  std::vector<double> ends, feeds;
  for (int k = 1; k <= 40; ++k) {
    ends.push_back(0.2 * k);
    feeds.push_back(60 * 30.0);
  }
  const PlannerTime t = Predict(LinearAccelMachine(), LineAlongX(ends, feeds));
  const double v = std::sqrt(kTangential * 0.2);
  EXPECT_EQ(t.capped_moves, 40);
  EXPECT_NEAR(t.time_s, 8.0 / v + 2 * v / (2 * kTangential), 1e-12);
  EXPECT_NEAR(t.time_s,
              BruteForceTime(ends, std::vector<double>(40, v), kTangential),
              1e-6);
}

TEST(PlannerTimeTest, EachAxisLimitScalesWithItsShareOfTheMove) {
  // A move along (3, 4, 0): X takes 3/5 of the path, Y 4/5. Y's velocity
  // limit 8 mm/s allows 10 mm/s along it, X's acceleration 90 allows 150.
  Machine m;
  m.limits[kX].max_acceleration = 90.0;
  m.limits[kY].max_velocity = 8.0;
  ToolPath path = LineAlongX({0.0}, {6000.0});
  path.poses[1].p_w_tip = Eigen::Vector3d(30, 40, 0);
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  const PlannerMove move = PlanMove(m, path, joints, 0, PlannerOptions());
  EXPECT_NEAR(move.length, 50.0, 1e-12);
  EXPECT_NEAR(move.requested_speed, 100.0, 1e-9);
  EXPECT_NEAR(move.tangential_acceleration, 0.5 * 150.0, 1e-9);
  EXPECT_NEAR(move.max_speed, 10.0, 1e-9);
  EXPECT_NEAR(move.speed, 10.0, 1e-9);
}

TEST(PlannerTimeTest, RotaryOnlyMovesAreInDegrees) {
  // A turn of C by 9 deg at F 540 (deg/min: 9 deg/s) with C's limits
  // 6 deg/s and 120 deg/s^2: C's velocity limit binds.
  Machine m;
  m.limits[kC].max_velocity = 6.0 * M_PI / 180;
  m.limits[kC].max_acceleration = 120.0 * M_PI / 180;
  ToolPath path;
  ToolPose p;
  p.p_w_tip = Eigen::Vector3d::Zero();
  p.a_w = AnglesToAxis(0.5, 0.0);
  path.poses.push_back(p);
  p.a_w = AnglesToAxis(0.5, 9.0 * M_PI / 180);
  p.feed_mm_per_min = 540.0;
  path.poses.push_back(p);
  std::vector<JointVector> joints;
  ASSERT_TRUE(m.AssignJoints(path, &joints).ok());
  const PlannerMove move = PlanMove(m, path, joints, 0, PlannerOptions());
  EXPECT_TRUE(move.rotary_only);
  EXPECT_NEAR(move.length, 9.0, 1e-9);
  EXPECT_NEAR(move.speed, 6.0, 1e-9);
  const PlannerTime t = PredictPlannerTime(m, path, joints, PlannerOptions());
  EXPECT_NEAR(t.time_s, 9.0 / 6.0 + 2 * 6.0 / (2 * 60.0), 1e-9);
}

TEST(PlannerTimeTest, OptionsAreChecked) {
  PlannerOptions o;
  std::string why;
  EXPECT_TRUE(o.IsValid(&why));
  o.blend_acceleration_fraction = 0.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("fraction"), std::string::npos);
  o.blend_acceleration_fraction = 1.0;
  o.default_feed_mm_per_min = -1;
  EXPECT_FALSE(o.IsValid(&why));
}

}  // namespace
}  // namespace tpopt
