#include "solver/feed_scheduler.h"

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

Scheduled GenerateAndSchedule(const std::string& surface_name, const std::string& machine_name, double noise_deg) {
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
  EXPECT_TRUE(ScheduleFeed(machine, joints, FeedScheduleOptions(), &s.path, &s.report).ok());
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

TEST(FeedSchedulerTest, LeavesAFeasiblePathAlone) {
  // The clean hypar path at 1000 mm/min is within the jcde2022 limits.
  const Scheduled s = GenerateAndSchedule("hypar.json", "jcde2022_ac.json", 0.0);
  ASSERT_EQ(s.before.limit_violations, 0);
  EXPECT_EQ(s.report.moves_slowed, 0);
  EXPECT_NEAR(s.after.machining_time_s, s.before.machining_time_s, 1e-12);
}

TEST(FeedSchedulerTest, RejectsBadOptions) {
  FeedScheduleOptions o;
  std::string why;
  o.margin = 1.5;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("1.5"), std::string::npos);
}

}  // namespace
}  // namespace tpopt
