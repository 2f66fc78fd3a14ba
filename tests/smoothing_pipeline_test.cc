#include "solver/smoothing_pipeline.h"

#include <gtest/gtest.h>

#include "model/path_generator.h"
#include "model/random_cases.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

// With judge_on_input_range the output is judged on the grid of the
// input's covered range, point by point, whatever range the output itself
// covers: the high-accuracy solve of this path starting at u = 0.25 moves
// both end contacts inwards by ~0.003 in u, so its own grid would differ.
TEST(SmoothingPipelineTest, OutputIsJudgedOnTheInputsRange) {
  RuledSurface surface;
  Machine machine;
  testing::LoadImpellerBench(&surface, &machine);
  FlankPathOptions g;
  g.poses = 41;
  g.strategy = FlankStrategy::kDoublePointOffset;
  ToolPath full;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &full).ok());
  ToolPath input = full;
  input.poses.erase(input.poses.begin(), input.poses.begin() + 10);  // u from 0.25
  SmoothingSettings settings;
  settings.mode = SmoothingMode::kHighAccuracy;
  settings.accept_over_tolerance = true;
  settings.judge_on_input_range = true;
  settings.deviation.samples_u = 30;
  settings.deviation.samples_v = 5;
  SmoothingResult result;
  const Status s = RunSmoothing({&input, &surface, &*input.cutter, &machine}, settings, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const DeviationReport& in = *result.input_metrics.deviation;
  EXPECT_NEAR(in.u.front(), 0.25, 1e-3);
  EXPECT_NEAR(in.u.back(), 1.0, 1e-9);
  for (const PathMetrics* m : {&result.output_at_input_feed, &result.output_metrics}) {
    ASSERT_TRUE(m->deviation.has_value());
    EXPECT_EQ(m->deviation->u, in.u);
    EXPECT_EQ(m->deviation->v, in.v);
  }
}

// Random case 176 covers u from 0.0032 to 1, where the input's grid's last
// point u_min + (1 - u_min) (n - 1) / (n - 1) rounds past 1: the output is
// judged on the range itself, not on the grid's end values.
TEST(SmoothingPipelineTest, InputRangeEndingAtOneIsAValidRange) {
  RandomCaseOptions options;
  options.poses = 40;
  RandomCase c;
  ASSERT_TRUE(MakeRandomCase(176, options, testing::SharedMachines(), &c).ok());
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  ASSERT_GT(u_min, 0.0);
  ASSERT_EQ(u_max, 1.0);
  SmoothingSettings settings;
  settings.mode = SmoothingMode::kSpline;
  settings.judge_on_input_range = true;
  SmoothingResult result;
  const Status s = testing::SmoothRandomCase(c, settings, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(result.output_metrics.deviation->u.size(), result.input_metrics.deviation->u.size());
  EXPECT_NEAR(result.output_metrics.deviation->u.back(), 1.0, 1e-12);
}

}  // namespace
}  // namespace tpopt
