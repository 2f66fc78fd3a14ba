#include "solver/smooth/feed_scheduler.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "model/machine/axis_metrics.h"
#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

struct Scheduled {
  MotionReport before, after;
  ToolPath path;
  FeedScheduleReport report;
};

// The path at `feed_mm_per_min`. Raising a feed needs one below what the
// planner can reach on the moves (model/machine/planner_time.h): on the hypar's
// 0.2 mm moves jcde2022's rotary limits allow a_t = 38 mm/s^2 along the
// path, so 60 sqrt(a_t L) = 165 mm/min.
Scheduled GenerateAndSchedule(const std::string& surface_name, const std::string& machine_name, double noise_deg,
                              const FeedScheduleOptions& options = FeedScheduleOptions(),
                              double feed_mm_per_min = 1000.0) {
  RuledSurface surface;
  Machine machine;
  EXPECT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/" + surface_name), &surface).ok());
  EXPECT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/" + machine_name), &machine).ok());
  FlankPathOptions g;
  g.axis_noise_deg = noise_deg;
  g.feed_mm_per_min = feed_mm_per_min;
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
  const Scheduled s = GenerateAndSchedule("hypar.json", "jcde2022_ac.json", 0.0, raise, 100.0);
  EXPECT_EQ(s.after.limit_violations, 0);
  EXPECT_GT(s.report.moves_raised, 0);
  EXPECT_LT(s.after.machining_time_s, s.before.machining_time_s);
  EXPECT_LE(s.report.max_feed_mm_per_min, 300.0);
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

// Straight moves along X from 0 through `ends_mm`, axis vertical, each
// taking `times_s` at the programmed feed (an inverse-time program's way).
ToolPath TimedLineAlongX(const std::vector<double>& ends_mm, const std::vector<double>& times_s) {
  ToolPath path;
  ToolPose pose;
  path.poses.push_back(pose);
  double x = 0.0;
  for (size_t k = 0; k < ends_mm.size(); ++k) {
    pose.p_w_tip.x() = ends_mm[k];
    pose.feed_mm_per_min = 60.0 * (ends_mm[k] - x) / times_s[k];
    x = ends_mm[k];
    path.poses.push_back(pose);
  }
  return path;
}

double PathTime(const Machine& machine, const ToolPath& path) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(machine.AssignJoints(path, &joints).ok());
  return EvaluateMotion(machine, path, joints, MotionOptions()).machining_time_s;
}

Scheduled ScheduleLine(const Machine& machine, ToolPath path, const FeedScheduleOptions& options) {
  Scheduled s;
  std::vector<JointVector> joints;
  EXPECT_TRUE(machine.AssignJoints(path, &joints).ok());
  s.before = EvaluateMotion(machine, path, joints, MotionOptions());
  EXPECT_TRUE(ScheduleFeed(machine, joints, options, &path, &s.report).ok());
  s.after = EvaluateMotion(machine, path, joints, MotionOptions());
  s.path = std::move(path);
  return s;
}

TEST(FeedSchedulerTest, RaisedFeedsAskNoAxisMoreThanTheInputsOwnPeaks) {
  // The tip runs along X at 1 mm a move while A tilts from 20 to 30 deg
  // over x in [55, 65] (a smoothstep) about C = 90 deg: A accelerates there
  // only. At 3x the feed with the input's A and C peaks as ceilings, A and
  // C accelerate and jerk no harder than in the input, and the moves away
  // from the tilt are raised; without the ceilings A accelerates harder.
  const Machine machine;  // no limits: only the input's peaks bind
  ToolPath path;
  for (int k = 0; k <= 120; ++k) {
    const double u = std::clamp((k - 55) / 10.0, 0.0, 1.0);
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(k, 0, 0);
    pose.a_w = AnglesToAxis((20.0 + 10.0 * u * u * (3 - 2 * u)) * kDeg, 90 * kDeg);
    pose.feed_mm_per_min = 100.0;
    path.poses.push_back(pose);
  }
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  const MotionReport input = EvaluateMotion(machine, path, joints, MotionOptions());
  FeedScheduleOptions raise = Raise(3.0, 1e6);
  raise.keep_input_peaks = false;
  const Scheduled free = ScheduleLine(machine, path, raise);
  for (int a : {kA, kC}) {
    raise.input_peak_acceleration[a] = input.axes[a].peak_acceleration;
    raise.input_peak_jerk[a] = input.axes[a].peak_jerk;
  }
  raise.keep_input_peaks = true;
  const Scheduled held = ScheduleLine(machine, path, raise);
  for (int a : {kA, kC}) {
    EXPECT_LE(held.after.axes[a].peak_acceleration, input.axes[a].peak_acceleration * (1 + 1e-9))
        << a;
    EXPECT_LE(held.after.axes[a].peak_jerk, input.axes[a].peak_jerk * (1 + 1e-9)) << a;
  }
  EXPECT_GT(free.after.axes[kA].peak_acceleration, 2 * input.axes[kA].peak_acceleration);
  EXPECT_GT(held.report.moves_raised, 20);
  EXPECT_LT(held.after.machining_time_s, 0.8 * input.machining_time_s);
  EXPECT_LT(free.after.machining_time_s, held.after.machining_time_s);
}

TEST(FeedSchedulerTest, RaisedFeedsStopAtWhatThePlannerCanReach) {
  // 0.2 mm moves at 60 mm/min, factor 100: a planner blending at half of
  // X's 300 mm/s^2 reaches sqrt(150 * 0.2) mm/s on each (model/machine/planner_time.h).
  Machine machine;
  machine.limits[kX].max_acceleration = 300.0;
  std::vector<double> ends, times;
  for (int k = 1; k <= 30; ++k) {
    ends.push_back(0.2 * k);
    times.push_back(0.2);
  }
  const Scheduled s = ScheduleLine(machine, TimedLineAlongX(ends, times), Raise(100.0, 1e6));
  for (size_t i = 1; i < s.path.poses.size(); ++i) {
    EXPECT_NEAR(s.path.poses[i].feed_mm_per_min, 60.0 * std::sqrt(30.0), 1e-9) << i;
  }
}

FeedScheduleOptions KeepRunTime(double window_mm) {
  FeedScheduleOptions o;
  o.mode = FeedMode::kKeepRunTime;
  o.keep_run_time_window_mm = window_mm;
  return o;
}

TEST(FeedSchedulerTest, KeepRunTimeGivesEachRunOneSpeedThatKeepsItsTime) {
  // Moves of 1 and 0.25 mm in turn, each 0.4 s (a G93 program's fixed
  // time), then a rapid and a second run of 0.5 mm moves of 0.1 s: with an
  // unbounded window each run moves at its own length / time.
  std::vector<double> ends, times;
  double x = 0.0;
  for (int k = 0; k < 20; ++k) {
    x += k % 2 == 0 ? 1.0 : 0.25;
    ends.push_back(x);
    times.push_back(0.4);
  }
  ToolPath path = TimedLineAlongX(ends, times);
  const double first_mm = x, first_s = 20 * 0.4;
  ToolPose rapid = path.poses.back();
  rapid.p_w_tip.z() = 5.0;
  rapid.rapid = true;
  path.poses.push_back(rapid);
  for (int k = 1; k <= 10; ++k) {
    ToolPose p = rapid;
    p.rapid = false;
    p.p_w_tip.x() += 0.5 * k;
    p.feed_mm_per_min = 60.0 * 0.5 / 0.1;
    path.poses.push_back(p);
  }
  const Machine machine;
  const Scheduled s = ScheduleLine(machine, path, KeepRunTime(INFINITY));
  EXPECT_EQ(s.report.runs_retimed, 2);
  for (size_t i = 1; i <= 20; ++i) {
    EXPECT_NEAR(s.path.poses[i].feed_mm_per_min, 60.0 * first_mm / first_s, 1e-9) << i;
  }
  for (size_t i = 22; i < s.path.poses.size(); ++i) {
    EXPECT_NEAR(s.path.poses[i].feed_mm_per_min, 60.0 * 5.0, 1e-9) << i;
  }
  EXPECT_NEAR(s.after.machining_time_s, s.before.machining_time_s, 1e-9);
  EXPECT_NEAR(PathTime(machine, s.path), PathTime(machine, path), 1e-9);
}

TEST(FeedSchedulerTest, KeepRunTimeFollowsTheProgramsMeanSpeedOverTheWindow) {
  // 20 moves of 1 mm at 0.5 s, then 20 at 0.25 s: with a 4 mm window a move
  // more than 2 mm from the change sees only its own half's mean speed, so
  // the second half runs exactly twice as fast as the first, and the run
  // takes its 15 s.
  std::vector<double> ends, times;
  for (int k = 1; k <= 40; ++k) {
    ends.push_back(k);
    times.push_back(k <= 20 ? 0.5 : 0.25);
  }
  const Machine machine;
  const Scheduled s = ScheduleLine(machine, TimedLineAlongX(ends, times), KeepRunTime(4.0));
  const double slow = s.path.poses[1].feed_mm_per_min;
  for (size_t i = 1; i <= 18; ++i) EXPECT_NEAR(s.path.poses[i].feed_mm_per_min, slow, 1e-9) << i;
  for (size_t i = 23; i <= 40; ++i) {
    EXPECT_NEAR(s.path.poses[i].feed_mm_per_min, 2 * slow, 1e-9) << i;
  }
  for (size_t i = 19; i <= 22; ++i) {  // the change is spread over the window
    EXPECT_GT(s.path.poses[i].feed_mm_per_min, slow) << i;
    EXPECT_LT(s.path.poses[i].feed_mm_per_min, 2 * slow) << i;
  }
  EXPECT_NEAR(s.after.machining_time_s, 15.0, 1e-9);
}

TEST(FeedSchedulerTest, KeepRunTimeStillKeepsTheLimits) {
  // The same run with X's velocity limit below its new speed: the limit
  // wins, as in the default mode.
  std::vector<double> ends, times;
  for (int k = 1; k <= 20; ++k) {
    ends.push_back(k % 2 == 0 ? k * 0.5 : k * 0.5);
    times.push_back(k % 4 == 0 ? 0.1 : 0.3);
  }
  Machine machine;
  machine.limits[kX].max_velocity = 2.0;  // mm/s; the run's mean is 2.27
  const Scheduled s = ScheduleLine(machine, TimedLineAlongX(ends, times), KeepRunTime(INFINITY));
  EXPECT_EQ(s.after.limit_violations, 0);
  EXPECT_GT(s.report.moves_slowed, 0);
  for (size_t i = 1; i < s.path.poses.size(); ++i) {
    EXPECT_LE(s.path.poses[i].feed_mm_per_min, 120.0) << i;
  }
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
  o = FeedScheduleOptions();
  o.keep_run_time_window_mm = 0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("--keep_run_time_window_mm must be > 0 (got 0)"), std::string::npos);
}

}  // namespace
}  // namespace tpopt
