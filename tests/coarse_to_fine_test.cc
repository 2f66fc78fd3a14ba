// Coarse-to-fine solve: station choice, exact interpolation of what a
// not-a-knot cubic spline can represent, and the same optimum as the direct
// solve on a dense path.
#include "solver/smooth/coarse_to_fine.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/eval/path_metrics.h"
#include "solver/smooth/ceres_smoother.h"
#include "solver/spline/spline_smoother.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Poses at tip arc length s = 0.1 i along x, A and C linear in s (or, with
// `bend`, cubic in s and curved at every end), with a rapid to a second run
// at pose 37.
ToolPath LinearPath(int n, double bend = 0.0) {
  ToolPath path;
  path.cutter = Cutter{4.0, 30.0, 0.0};
  for (int i = 0; i < n; ++i) {
    const double s = 0.1 * i;
    ToolPose p;
    p.p_w_tip = Eigen::Vector3d(s, 2.0, -1.0);
    const double cubic = bend * (0.3 * s * s - 0.01 * s * s * s);
    p.a_w = AnglesToAxis((20.0 + 0.5 * s + cubic) * kDeg, (-30.0 + 2.0 * s - cubic) * kDeg);
    p.rapid = i == 37;
    path.poses.push_back(p);
  }
  return path;
}

TEST(CoarseStationsTest, KeepsRunEndsRapidTargetsAndEveryStridePose) {
  const ToolPath path = LinearPath(100);
  const std::vector<size_t> stations = CoarseStations(path, 10);  // stride 10
  auto has = [&](size_t i) {
    return std::find(stations.begin(), stations.end(), i) != stations.end();
  };
  EXPECT_TRUE(has(0));
  EXPECT_TRUE(has(36));  // the run's last pose
  EXPECT_TRUE(has(37));  // the rapid target
  EXPECT_TRUE(has(99));
  for (size_t i = 0; i < 100; i += 10) EXPECT_TRUE(has(i)) << i;
  EXPECT_EQ(stations.size(), 13u);  // 0..90 by 10, 36, 37, 99
  EXPECT_TRUE(std::is_sorted(stations.begin(), stations.end()));
  // Every move of the subpath keeps its kind: only 37 arrives by rapid.
  const ToolPath sub = SubPath(path, stations);
  for (size_t j = 0; j < stations.size(); ++j) {
    EXPECT_EQ(sub.poses[j].rapid, stations[j] == 37) << j;
  }
}

// Joints cubic in the arc length and curved at the runs' ends, where a
// natural spline would straighten them: the finer level's start would then
// carry a false third derivative in every run's first and last step.
TEST(InterpolateStationsTest, ReproducesJointsCubicInArcLength) {
  Machine machine;
  ASSERT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &machine).ok());
  const ToolPath fine = LinearPath(100, /*bend=*/1.0);
  const std::vector<size_t> stations = CoarseStations(fine, 12);
  ToolPath out;
  ASSERT_TRUE(InterpolateStations(fine, stations, SubPath(fine, stations), machine, &out).ok());
  for (size_t i = 0; i < fine.poses.size(); ++i) {
    EXPECT_LT((out.poses[i].a_w - fine.poses[i].a_w).norm(), 1e-9) << i;
  }
}

TEST(InterpolateStationsTest, ReproducesPosesLinearInArcLength) {
  Machine machine;
  ASSERT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &machine).ok());
  const ToolPath fine = LinearPath(100);
  const std::vector<size_t> stations = CoarseStations(fine, 12);
  // Shift every fine pose (which keeps the arc length): the result must
  // come from the stations alone.
  ToolPath shifted = fine;
  for (ToolPose& p : shifted.poses) p.p_w_tip.y() += 5.0;
  const ToolPath coarse = SubPath(fine, stations);
  ToolPath out;
  ASSERT_TRUE(InterpolateStations(shifted, stations, coarse, machine, &out).ok());
  ASSERT_EQ(out.poses.size(), fine.poses.size());
  for (size_t i = 0; i < fine.poses.size(); ++i) {
    EXPECT_LT((out.poses[i].p_w_tip - fine.poses[i].p_w_tip).norm(), 1e-9) << i;
    EXPECT_LT((out.poses[i].a_w - fine.poses[i].a_w).norm(), 1e-9) << i;
    EXPECT_EQ(out.poses[i].rapid, fine.poses[i].rapid) << i;
  }
}

// The direct solve, coarse to fine, and windowed without coarse levels,
// on the same dense distorted impeller path: the same deviation.
// A 900-pose CAM path on the impeller blade, distorted and noisy.
void DistortedImpellerPath(const RuledSurface& surface, ToolPath* path) {
  FlankPathOptions g;
  g.poses = 900;
  g.uv_distortion = 0.03;
  g.axis_noise_deg = 0.3;
  ASSERT_TRUE(GenerateFlankPath(surface, g, path).ok());
}

TEST(CoarseToFineSolveTest, CoarseToFineAndWindowsMatchTheDirectSolve) {
  RuledSurface surface;
  Machine machine;
  ASSERT_NO_FATAL_FAILURE(testing::LoadImpellerBench(&surface, &machine));
  ToolPath input, guess;
  ASSERT_NO_FATAL_FAILURE(DistortedImpellerPath(surface, &input));
  SplineSmootherReport spline_report;
  ASSERT_TRUE(SmoothWithSplines(input, machine, &surface, *input.cutter, SplineSmootherOptions(),
                                &guess, &spline_report)
                  .ok());
  const SmoothingInputs inputs{&input, &guess, &surface, &*input.cutter, &machine};
  struct Variant {
    int coarse_poses, window_poses;
  };
  // Direct; 900 -> 112 stations; four windows of 300 with 30 overlapping.
  const Variant variants[] = {{0, 0}, {100, 0}, {0, 300}};
  PathMetrics metrics[3];
  for (int k = 0; k < 3; ++k) {
    HighAccuracyOptions options;
    options.coarse_poses = variants[k].coarse_poses;
    options.window_poses = variants[k].window_poses;
    ToolPath out;
    HighAccuracyReport report;
    ASSERT_TRUE(SmoothHighAccuracy(inputs, options, &out, &report).ok());
    EXPECT_TRUE(report.converged) << k;
    ASSERT_TRUE(EvaluatePath(out, machine, &surface, *input.cutter, DeviationOptions(),
                             MotionOptions(), &metrics[k])
                    .ok());
    ASSERT_TRUE(metrics[k].deviation);
  }
  const double tolerance_mm = HighAccuracyOptions().tolerance_mm;
  const DeviationReport& direct = *metrics[0].deviation;
  for (int k = 1; k < 3; ++k) {
    const DeviationReport& d = *metrics[k].deviation;
    EXPECT_LT(d.max_overcut_mm, tolerance_mm) << k;
    EXPECT_LT(d.max_undercut_mm, tolerance_mm) << k;
    EXPECT_NEAR(d.max_overcut_mm, direct.max_overcut_mm, 1e-3) << k;
    EXPECT_NEAR(d.max_undercut_mm, direct.max_undercut_mm, 1e-3) << k;
    EXPECT_NEAR(d.rms_deviation_mm, direct.rms_deviation_mm, 3e-4) << k;
  }
}

// Held poses (a window's seams, solver/spline/pole_passage.h) stay exactly at
// the guess through the coarse levels and the windows, however the path is
// solved, while the poses next to them move.
TEST(CoarseToFineSolveTest, HeldPosesKeepTheGuessAtEveryLevelAndWindow) {
  RuledSurface surface;
  Machine machine;
  ASSERT_NO_FATAL_FAILURE(testing::LoadImpellerBench(&surface, &machine));
  ToolPath input;
  ASSERT_NO_FATAL_FAILURE(DistortedImpellerPath(surface, &input));
  SmoothingInputs inputs{&input, &input, &surface, &*input.cutter, &machine};
  inputs.held_first = 5;
  inputs.held_last = 4;
  // 900 -> 112 stations (held poses off the stride among them); windows of 300.
  for (const int window_poses : {0, 300}) {
    HighAccuracyOptions options;
    options.coarse_poses = 100;
    options.window_poses = window_poses;
    options.max_iterations = 20;
    ToolPath out;
    HighAccuracyReport report;
    ASSERT_TRUE(SmoothHighAccuracy(inputs, options, &out, &report).ok());
    const size_t n = input.poses.size();
    for (size_t i = 0; i < n; ++i) {
      const bool held = i < inputs.held_first || i + inputs.held_last >= n;
      const double moved = (out.poses[i].p_w_tip - input.poses[i].p_w_tip).norm() +
                           (out.poses[i].a_w - input.poses[i].a_w).norm();
      if (held) {
        EXPECT_EQ(moved, 0.0) << "pose " << i << ", windows " << window_poses;
      } else if (i == inputs.held_first || i + inputs.held_last + 1 == n) {
        EXPECT_GT(moved, 1e-6) << "pose " << i << ", windows " << window_poses;
      }
    }
  }
}

}  // namespace
}  // namespace tpopt
