// Whole-smoother tests: final metrics, never raw parameters.
#include "solver/ceres_smoother.h"

#include <gtest/gtest.h>

#include "model/json_io.h"
#include "model/path_generator.h"
#include "model/path_metrics.h"
#include "solver/spline_smoother.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

class CeresSmootherTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(
        ReadSurfaceJson(testing::SourcePath("data/surfaces/impeller_blade.json"), &surface_).ok());
    ASSERT_TRUE(
        ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &machine_).ok());
    FlankPathOptions g;
    g.poses = 150;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &clean_).ok());
    g.strategy = FlankStrategy::kDoublePointOffset;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &dpo_).ok());
    cutter_ = *clean_.cutter;
    spiked_ = clean_;
    for (int i = 74; i <= 76; ++i) {  // one injected spike of 3 deg
      ToolPose& p = spiked_.poses[i];
      const Eigen::Vector3d tangent = (clean_.poses[i + 1].p_w_tip - p.p_w_tip).normalized();
      p.a_w = Eigen::AngleAxisd(3 * kDeg, tangent) * p.a_w;
    }
  }

  PathMetrics Evaluate(const ToolPath& path) {
    PathMetrics m;
    EXPECT_TRUE(EvaluatePath(path, machine_, &surface_, cutter_, DeviationOptions(),
                             MotionOptions(), &m)
                    .ok());
    return m;
  }

  ToolPath Smooth(const ToolPath& input, HighAccuracyReport* report) {
    ToolPath guess, out;
    SplineSmootherReport spline_report;
    EXPECT_TRUE(SmoothWithSplines(input, machine_, &surface_, cutter_, SplineSmootherOptions(),
                                  &guess, &spline_report)
                    .ok());
    HighAccuracyOptions options;
    options.progress = false;
    const SmoothingInputs inputs{&input, &guess, &surface_, &cutter_, &machine_};
    EXPECT_TRUE(SmoothHighAccuracy(inputs, options, &out, report).ok());
    return out;
  }

  RuledSurface surface_;
  Machine machine_;
  Cutter cutter_;
  ToolPath clean_, dpo_, spiked_;
};

TEST_F(CeresSmootherTest, SmoothsAnInjectedSpikeAndBeatsDpoOnDeviation) {
  HighAccuracyReport report;
  const ToolPath out = Smooth(spiked_, &report);
  ASSERT_TRUE(report.converged) << report.message;
  EXPECT_LT(report.final_cost, report.initial_cost);
  const PathMetrics m = Evaluate(out), spiked = Evaluate(spiked_), clean = Evaluate(clean_),
                    dpo = Evaluate(dpo_);
  // Within twice the tolerance, and at most 0.7x the best classical offset.
  EXPECT_LT(WorstDeviationMm(m), 2 * HighAccuracyOptions().tolerance_mm);
  EXPECT_LT(WorstDeviationMm(m), 0.7 * WorstDeviationMm(dpo));
  for (int axis : {kA, kC}) {
    const double c = clean.motion.axes[axis].peak_second_derivative_per_mm2;
    EXPECT_GT(spiked.motion.axes[axis].peak_second_derivative_per_mm2, 10 * c) << axis;
    EXPECT_LT(m.motion.axes[axis].peak_second_derivative_per_mm2, 2 * c) << axis;
  }
  EXPECT_GT(report.final_cost_by_family.count("deviation"), 0u);
  EXPECT_GT(report.iterations, 0);
}

TEST_F(CeresSmootherTest, IsDeterministic) {
  HighAccuracyReport r1, r2;
  const ToolPath a = Smooth(spiked_, &r1), b = Smooth(spiked_, &r2);
  EXPECT_EQ(r1.final_cost, r2.final_cost);
  const PathMetrics ma = Evaluate(a), mb = Evaluate(b);
  EXPECT_EQ(ma.deviation->max_overcut_mm, mb.deviation->max_overcut_mm);
  EXPECT_EQ(ma.deviation->max_undercut_mm, mb.deviation->max_undercut_mm);
  EXPECT_EQ(ma.motion.axes[kC].peak_acceleration, mb.motion.axes[kC].peak_acceleration);
}

TEST_F(CeresSmootherTest, RejectsMismatchedInputsAndBadOptions) {
  ToolPath shorter = clean_;
  shorter.poses.pop_back();
  HighAccuracyOptions options;
  options.progress = false;
  ToolPath out;
  HighAccuracyReport report;
  const SmoothingInputs inputs{&clean_, &shorter, &surface_, &cutter_, &machine_};
  EXPECT_FALSE(SmoothHighAccuracy(inputs, options, &out, &report).ok());
  options.tolerance_mm = 0;
  const SmoothingInputs same{&clean_, &clean_, &surface_, &cutter_, &machine_};
  const Status s = SmoothHighAccuracy(same, options, &out, &report);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("tolerance 0"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace tpopt
