// The two ways round the A = 0 pole: finding the stretches where the axis
// circles close to +Z, taking one the other way round, and the solve that
// tries both on the hypar's distorted CAM path.
#include "solver/spline/pole_passage.h"

#include <gtest/gtest.h>

#include <cmath>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/eval/path_metrics.h"
#include "solver/smooth/both_ways_round_poles.h"
#include "solver/spline/spline_smoother.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Vector3d Axis(double polar, double azimuth) {
  return Eigen::Vector3d(std::sin(polar) * std::sin(azimuth),
                         std::sin(polar) * std::cos(azimuth), std::cos(polar));
}

// n poses along x; the axis tilted `polar(i)` from +Z with its azimuth
// turning linearly from 0 to `sweep`.
template <typename Polar>
ToolPath CirclingPath(int n, double sweep, Polar polar) {
  ToolPath path;
  for (int i = 0; i < n; ++i) {
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(0.5 * i, 0.0, 0.0);
    pose.a_w = Axis(polar(i), sweep * i / (n - 1));
    path.poses.push_back(pose);
  }
  return path;
}

TEST(FindPolePassagesTest, FindsTheStretchWithinThePoleAngle) {
  // Polar angle 20 deg at the ends, 2 deg over poses 10..29.
  const ToolPath path = CirclingPath(40, 200 * kDeg, [](int i) {
    return (i >= 10 && i < 30 ? 2.0 : 20.0) * kDeg;
  });
  const std::vector<PolePassage> passages = FindPolePassages(path, 5 * kDeg);
  ASSERT_EQ(passages.size(), 1u);
  EXPECT_EQ(passages[0].first, 10u);
  EXPECT_EQ(passages[0].last, 29u);
  EXPECT_NEAR(passages[0].azimuth_sweep_rad, 200 * kDeg * 19 / 39, 1e-9);
}

TEST(FindPolePassagesTest, IgnoresFarPassesSmallSweepsAndRapids) {
  auto polar_3deg = [](int) { return 3.0 * kDeg; };
  // Circling at 3 deg: a passage at a 5 deg pole angle, none at 2 deg.
  EXPECT_EQ(FindPolePassages(CirclingPath(30, 200 * kDeg, polar_3deg), 5 * kDeg)
                .size(),
            1u);
  EXPECT_TRUE(
      FindPolePassages(CirclingPath(30, 200 * kDeg, polar_3deg), 2 * kDeg)
          .empty());
  // A sweep under a quarter turn has no plausible other way round.
  EXPECT_TRUE(
      FindPolePassages(CirclingPath(30, 80 * kDeg, polar_3deg), 5 * kDeg)
          .empty());
  // A rapid splits the stretch: 0..14 sweeps 193 deg, 15..29 likewise.
  ToolPath split = CirclingPath(30, 400 * kDeg, polar_3deg);
  split.poses[15].rapid = true;
  const std::vector<PolePassage> passages = FindPolePassages(split, 5 * kDeg);
  ASSERT_EQ(passages.size(), 2u);
  EXPECT_EQ(passages[0].last, 14u);
  EXPECT_EQ(passages[1].first, 15u);
}

TEST(RerouteAroundPoleTest,
     TurnsTheOtherWayKeepingPolarAngleEndsAndFluteMiddle) {
  const ToolPath path = CirclingPath(
      40, 250 * kDeg, [](int i) { return (1.0 + 0.1 * i) * kDeg; });
  const std::vector<PolePassage> passages = FindPolePassages(path, 5 * kDeg);
  ASSERT_EQ(passages.size(), 1u);
  const Cutter cutter{4.0, 30.0, 0.0};
  const ToolPath other = RerouteAroundPole(path, passages[0], cutter);
  ASSERT_EQ(other.poses.size(), path.poses.size());
  // The same stretch, now turning 250 - 360 = -110 deg over it.
  const std::vector<PolePassage> rerouted = FindPolePassages(other, 5 * kDeg);
  ASSERT_EQ(rerouted.size(), 1u);
  EXPECT_NEAR(rerouted[0].azimuth_sweep_rad,
              passages[0].azimuth_sweep_rad - 2 * M_PI, 1e-9);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const ToolPose& a = path.poses[i];
    const ToolPose& b = other.poses[i];
    EXPECT_NEAR(b.a_w.norm(), 1.0, 1e-12) << i;
    EXPECT_NEAR(std::acos(b.a_w.z()), std::acos(a.a_w.z()), 1e-9) << i;
    // The cutter pivots about the middle of its flute.
    EXPECT_LT((b.p_w_tip + 15.0 * b.a_w - a.p_w_tip - 15.0 * a.a_w).norm(),
              1e-9)
        << i;
    const bool inside = i >= passages[0].first && i <= passages[0].last;
    if (!inside || i == passages[0].first || i == passages[0].last) {
      EXPECT_LT((b.a_w - a.a_w).norm(), 1e-9) << i;
    }
  }
  // Halfway through, the two routes lie on opposite sides of the pole.
  const size_t mid = (passages[0].first + passages[0].last) / 2;
  EXPECT_LT(path.poses[mid].a_w.head<2>().dot(other.poses[mid].a_w.head<2>()),
            0.0);
}

// The hypar's distorted CAM path passes within half a degree of the pole
// and goes round it on the wrong side; so does the spline guess made from
// it. Solving only from that guess keeps the wrong side; trying the other
// way finds the surface's side and meets the target there: at most
// 0.7 x the deviation of a clean double-point-offset path.
TEST(SmoothBothWaysRoundPolesTest, HyparCamPathTakesTheSurfacesSideOfThePole) {
  RuledSurface surface;
  Machine machine;
  ASSERT_NO_FATAL_FAILURE(testing::LoadHyparBench(&surface, &machine));
  FlankPathOptions g;
  g.strategy = FlankStrategy::kDoublePointOffset;
  ToolPath dpo;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &dpo).ok());
  g.strategy = FlankStrategy::kSinglePointOffset;
  g.uv_distortion = 0.03;
  g.axis_noise_deg = 0.3;
  ToolPath cam;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &cam).ok());
  // The guess as the pipeline makes it for high_accuracy.
  ToolPath guess;
  SplineSmootherReport spline_report;
  ASSERT_TRUE(SmoothWithSplines(cam, machine, &surface, *cam.cutter,
                                ForHighAccuracyGuess(SplineSmootherOptions()),
                                &guess, &spline_report)
                  .ok());
  const SmoothingInputs inputs{&cam, &guess, &surface, &*cam.cutter, &machine};
  const HighAccuracyOptions options;

  ToolPath one_way, both_ways;
  HighAccuracyReport one_way_report, both_ways_report;
  ASSERT_TRUE(
      SmoothHighAccuracy(inputs, options, &one_way, &one_way_report).ok());
  ASSERT_TRUE(
      SmoothBothWaysRoundPoles(inputs, options, &both_ways, &both_ways_report)
          .ok());
  ASSERT_TRUE(both_ways_report.converged);
  EXPECT_EQ(both_ways_report.pole_passages, 1);
  EXPECT_EQ(both_ways_report.pole_passages_rerouted, 1);
  EXPECT_EQ(both_ways_report.pole_passages_in_windows, 0);  // 300 poses: whole
  EXPECT_LT(both_ways_report.final_cost, 0.5 * one_way_report.final_cost);

  auto worst_mm = [&](const ToolPath& path) {
    PathMetrics m;
    EXPECT_TRUE(EvaluatePath(path, machine, &surface, *cam.cutter,
                             DeviationOptions(), MotionOptions(), &m)
                    .ok());
    return WorstDeviationMm(m);
  };
  const double dpo_mm = worst_mm(dpo);
  EXPECT_GT(worst_mm(one_way), 0.7 * dpo_mm);
  EXPECT_LE(worst_mm(both_ways), 0.7 * dpo_mm);
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

// Five passes of the hypar's distorted CAM path, one after another with a
// rapid before each: three passages, each far shorter than the path. Each
// is tried the other way in a window round it, not by solving the whole
// path again; the result is the path solved whole from the guess with all
// five passages taken the other way (the same basin), found at a bounded
// cost a passage.
TEST(SmoothBothWaysRoundPolesTest, PassagesOfALongPathAreResolvedInWindows) {
  RuledSurface surface;
  Machine machine;
  ASSERT_NO_FATAL_FAILURE(testing::LoadHyparBench(&surface, &machine));
  FlankPathOptions g;
  g.uv_distortion = 0.03;
  g.axis_noise_deg = 0.3;
  ToolPath pass;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &pass).ok());
  constexpr int kPasses = 5;
  const ToolPath cam = RepeatedPasses(pass, kPasses);
  ToolPath guess;
  SplineSmootherReport spline_report;
  ASSERT_TRUE(SmoothWithSplines(cam, machine, &surface, *cam.cutter,
                                ForHighAccuracyGuess(SplineSmootherOptions()), &guess,
                                &spline_report)
                  .ok());
  const SmoothingInputs inputs{&cam, &guess, &surface, &*cam.cutter, &machine};
  HighAccuracyOptions options;
  options.pole_window_path_poses = 1000;  // windows on this 1,500-pose path
  ToolPath windowed;
  HighAccuracyReport windowed_report;
  ASSERT_TRUE(SmoothBothWaysRoundPoles(inputs, options, &windowed, &windowed_report).ok());
  ASSERT_TRUE(windowed_report.converged);
  EXPECT_EQ(windowed_report.pole_passages, kPasses);
  EXPECT_EQ(windowed_report.pole_passages_rerouted, kPasses);
  EXPECT_EQ(windowed_report.pole_passages_in_windows, kPasses);

  // The reference: every passage rerouted in the guess, one whole solve.
  const std::vector<PolePassage> passages = FindPolePassages(guess, 5.0 * M_PI / 180.0);
  ASSERT_EQ(passages.size(), static_cast<size_t>(kPasses));
  ToolPath rerouted = guess;
  for (const PolePassage& p : passages) rerouted = RerouteAroundPole(rerouted, p, *cam.cutter);
  SmoothingInputs whole_inputs = inputs;
  whole_inputs.initial_guess = &rerouted;
  ToolPath whole;
  HighAccuracyReport whole_report;
  ASSERT_TRUE(SmoothHighAccuracy(whole_inputs, options, &whole, &whole_report).ok());

  auto worst_mm = [&](const ToolPath& path) {
    PathMetrics m;
    EXPECT_TRUE(EvaluatePath(path, machine, &surface, *cam.cutter, DeviationOptions(),
                             MotionOptions(), &m)
                    .ok());
    return WorstDeviationMm(m);
  };
  // Measured: cost 0.111 against 0.170, worst deviation 0.0168 against
  // 0.0236 mm (the windows refine each passage from a converged path).
  EXPECT_LE(windowed_report.final_cost, 1.05 * whole_report.final_cost);
  EXPECT_LE(worst_mm(windowed), 1.05 * worst_mm(whole));
}

}  // namespace
}  // namespace tpopt
