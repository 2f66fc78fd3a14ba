#include "solver/feed_scheduler.h"

#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "model/axis_metrics.h"
#include "model/json_io.h"
#include "model/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

struct Scheduled {
  MotionReport before, after;
  ToolPath path;
  FeedScheduleReport report;
};

Scheduled GenerateAndSchedule(const std::string& surface_name, const std::string& machine_name, double noise_deg,
                              const FeedScheduleOptions& options = FeedScheduleOptions()) {
  RuledSurface surface;
  Machine machine;
  EXPECT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/" + surface_name), &surface).ok());
  EXPECT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/" + machine_name), &machine).ok());
  FlankPathOptions g;
  g.axis_noise_deg = noise_deg;
  Scheduled s;
  EXPECT_TRUE(GenerateFlankPath(surface, g, &s.path).ok());
  std::vector<JointVector> joints;
  EXPECT_TRUE(machine.AssignJoints(s.path, &joints).ok());
  s.before = EvaluateMotion(machine, s.path, joints, MotionOptions());
  EXPECT_TRUE(ScheduleFeed(machine, joints, options, &s.path, &s.report).ok());
  s.after = EvaluateMotion(machine, s.path, joints, MotionOptions());
  return s;
}

TEST(FeedSchedulerTest, RemovesEveryViolationOfANoisyPath) {
  for (const char* machine : {"jcde2022_ac.json", "linuxcnc_xyzac_trt_sim.json"}) {
    const Scheduled s = GenerateAndSchedule("impeller_blade.json", machine, 0.3);
    EXPECT_GT(s.before.limit_violations, 100) << machine;
    EXPECT_EQ(s.after.limit_violations, 0) << machine;
    EXPECT_EQ(s.report.violations_left, 0) << machine;
    EXPECT_GT(s.after.machining_time_s, s.before.machining_time_s) << machine;
    for (const ToolPose& p : s.path.poses) EXPECT_LE(p.feed_mm_per_min, 1000.0);
  }
}

TEST(FeedSchedulerTest, RaisedFeedsOfAGeneratedPathKeepEveryLimitAndTheStep) {
  FeedScheduleOptions raise;
  raise.mode = FeedMode::kRaise;
  raise.max_feed_factor = 3.0;
  const Scheduled s = GenerateAndSchedule("hypar.json", "jcde2022_ac.json", 0.0, raise);
  EXPECT_EQ(s.after.limit_violations, 0);
  EXPECT_GT(s.report.moves_raised, 0);
  EXPECT_LT(s.after.machining_time_s, s.before.machining_time_s);
  EXPECT_LE(s.report.max_feed_mm_per_min, 3000.0);
  for (size_t i = 2; i < s.path.poses.size(); ++i) {
    const double ratio = s.path.poses[i].feed_mm_per_min / s.path.poses[i - 1].feed_mm_per_min;
    EXPECT_LE(std::max(ratio, 1 / ratio), 1.1 + 1e-12) << i;
  }
}

TEST(FeedSchedulerTest, LeavesAFeasiblePathAlone) {
  // The clean hypar path at 1000 mm/min is within the jcde2022 limits.
  const Scheduled s = GenerateAndSchedule("hypar.json", "jcde2022_ac.json", 0.0);
  ASSERT_EQ(s.before.limit_violations, 0);
  EXPECT_EQ(s.report.moves_slowed, 0);
  EXPECT_NEAR(s.after.machining_time_s, s.before.machining_time_s, 1e-12);
}

constexpr double kDeg = M_PI / 180.0;

// A pure C rotation: the joints X = 30 mm, Y = Z = 0, A = 30 deg stay, C
// turns by `step_deg` a move, so the tip runs round the C axis on a circle.
ToolPath CRotation(const Machine& machine, int moves, double step_deg, double feed_mm_per_min) {
  ToolPath path;
  for (int k = 0; k <= moves; ++k) {
    JointVector j;
    j << 30, 0, 0, 30 * kDeg, k * step_deg * kDeg;
    ToolPose pose;
    machine.ToWorkpiece(j, &pose.p_w_tip, &pose.a_w);
    pose.feed_mm_per_min = feed_mm_per_min;
    path.poses.push_back(pose);
  }
  return path;
}

Machine OnlyCLimited(double c_max_velocity_deg_per_s) {
  Machine m;
  m.limits[kC].max_velocity = c_max_velocity_deg_per_s * kDeg;
  return m;
}

FeedScheduleOptions Raise(double max_feed_factor, double max_feed_mm_per_min) {
  FeedScheduleOptions o;
  o.mode = FeedMode::kRaise;
  o.max_feed_factor = max_feed_factor;
  o.max_feed_mm_per_min = max_feed_mm_per_min;
  return o;
}

// On the circle of radius r a move of chord 2 r sin(d/2) turns C by d, so
// at feed F C turns at d F / (2 r sin(d/2)); C's limit v gives the largest
// feed F = v 2 r sin(d/2) / d, and the scheduler aims at margin * v.
TEST(FeedSchedulerTest, RaisesAPureCRotationToTheFeedOfCsVelocityLimit) {
  const Machine machine = OnlyCLimited(10.0);
  const double step_deg = 1.0;
  ToolPath path = CRotation(machine, 40, step_deg, 100.0);
  const double r_mm = std::hypot(path.poses[0].p_w_tip.x(), path.poses[0].p_w_tip.y());
  ASSERT_NEAR(r_mm, 30.0, 1e-9);
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  const FeedScheduleOptions options = Raise(1000.0, 1e6);
  FeedScheduleReport report;
  ASSERT_TRUE(ScheduleFeed(machine, joints, options, &path, &report).ok());
  const double d = step_deg * kDeg;
  const double expected_mm_per_min =
      options.margin * 10.0 * kDeg * 2 * r_mm * std::sin(d / 2) / d * 60.0;
  for (size_t i = 1; i < path.poses.size(); ++i) {
    EXPECT_NEAR(path.poses[i].feed_mm_per_min, expected_mm_per_min, 1e-9 * expected_mm_per_min)
        << i;
  }
  EXPECT_EQ(report.moves_raised, 40);
  EXPECT_EQ(report.moves_slowed, 0);
  EXPECT_EQ(report.violations_left, 0);
  // The machining time is then the turn at 0.97 of C's limit.
  const MotionReport after = EvaluateMotion(machine, path, joints, MotionOptions());
  EXPECT_NEAR(after.machining_time_s, 40 * step_deg / (options.margin * 10.0), 1e-9);
  EXPECT_EQ(after.limit_violations, 0);
}

TEST(FeedSchedulerTest, RaisedFeedsStopAtTheUsersCeilings) {
  const Machine machine = OnlyCLimited(10.0);  // limit feed ~ 309 mm/min
  for (const auto& [factor, cap, expected] :
       {std::tuple<double, double, double>{1.5, 1e6, 150.0}, {1000.0, 250.0, 250.0}}) {
    ToolPath path = CRotation(machine, 10, 1.0, 100.0);
    std::vector<JointVector> joints;
    ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
    FeedScheduleReport report;
    ASSERT_TRUE(ScheduleFeed(machine, joints, Raise(factor, cap), &path, &report).ok());
    for (size_t i = 1; i < path.poses.size(); ++i) {
      EXPECT_DOUBLE_EQ(path.poses[i].feed_mm_per_min, expected) << factor << " " << cap;
    }
    EXPECT_EQ(report.max_feed_mm_per_min, expected);
  }
}

// Programmed 100 then 1000 mm/min, factor 2, no limit binding: the first
// half stays at 200 and the second climbs from it by at most 1.1 a move,
// min(2000, 200 * 1.1^k) k moves after the jump.
TEST(FeedSchedulerTest, RaisedNeighbouringFeedsStayWithinTheStep) {
  const Machine machine = OnlyCLimited(1e6);
  ToolPath path = CRotation(machine, 60, 1.0, 100.0);
  for (size_t i = 31; i < path.poses.size(); ++i) path.poses[i].feed_mm_per_min = 1000.0;
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  FeedScheduleReport report;
  ASSERT_TRUE(ScheduleFeed(machine, joints, Raise(2.0, 1e6), &path, &report).ok());
  for (size_t i = 1; i <= 30; ++i) EXPECT_DOUBLE_EQ(path.poses[i].feed_mm_per_min, 200.0) << i;
  for (size_t i = 31; i < path.poses.size(); ++i) {
    const double expected = std::min(2000.0, 200.0 * std::pow(1.1, static_cast<double>(i - 30)));
    EXPECT_NEAR(path.poses[i].feed_mm_per_min, expected, 1e-9 * expected) << i;
  }
  EXPECT_EQ(path.poses.back().feed_mm_per_min, 2000.0);
}

TEST(FeedSchedulerTest, RejectsBadOptions) {
  FeedScheduleOptions o;
  std::string why;
  o.margin = 1.5;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("1.5"), std::string::npos);
  o = FeedScheduleOptions();
  o.max_feed_factor = 0.5;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("0.5"), std::string::npos);
  o = FeedScheduleOptions();
  o.max_feed_mm_per_min = 0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("--max_feed_mm_per_min must be > 0 (got 0)"), std::string::npos);
}

}  // namespace
}  // namespace tpopt
