#include "model/eval/path_metrics.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

PathMetrics Metrics(double overcut_mm, double undercut_mm, int violations) {
  PathMetrics m;
  m.deviation = DeviationReport();
  m.deviation->max_overcut_mm = overcut_mm;
  m.deviation->max_undercut_mm = undercut_mm;
  m.motion.limit_violations = violations;
  return m;
}

TEST(PathMetricsTest, WorseMeansWorseOnOneAndBetterOnNone) {
  const PathMetrics start = Metrics(0.05, 0.02, 10);
  EXPECT_EQ(WorstDeviationMm(start), 0.05);
  EXPECT_TRUE(IsWorseThan(Metrics(0.06, 0.0, 10), start));   // deviation worse
  EXPECT_TRUE(IsWorseThan(Metrics(0.05, 0.02, 11), start));  // limits worse
  EXPECT_FALSE(IsWorseThan(Metrics(0.06, 0.0, 9), start));   // a trade
  EXPECT_FALSE(IsWorseThan(Metrics(0.04, 0.0, 10), start));  // better
  EXPECT_FALSE(IsWorseThan(start, start));                   // equal is not worse
}

}  // namespace
}  // namespace tpopt
