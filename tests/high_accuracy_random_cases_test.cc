// The high-accuracy mode on fixed-seed random cases (model/eval/random_cases.h):
// surfaces and CAM conventions it was not built on. Each case asserts what
// issue 16 asks of the mode:
//  - success wherever the input fits the machine;
//  - max |dev| <= 1.0 x the clean DPO path's on the input's covered range,
//    both by the brute-force evaluator;
//  - peak d2A/ds2 and d2C/ds2 <= 2 x the clean SPO path's (in
//    RoughReference, whose clean DPO path is itself beyond that, within the
//    larger of it and the DPO path's own);
//  - every axis within its cone round the input's axis.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "apps/report.h"
#include "model/eval/deviation.h"
#include "model/eval/random_cases.h"
#include "model/io/json_io.h"
#include "model/machine/axis_metrics.h"
#include "model/machine/interpolation.h"
#include "model/path/path_generator.h"
#include "model/path/rail_projection.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "solver/smooth/tolerance_promise.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;
// The half angle of the cone each output axis must keep round its input
// axis: the default of issue 16's axis cone (HighAccuracyOptions).
constexpr double kConeDeg = 12.0;
constexpr int kPoses = 40;
// Brute-force evaluation: grid and uniform samples per move.
constexpr int kSamplesU = 60, kSamplesV = 7, kBruteSubsteps = 40;

const std::vector<Machine>& SharedMachines() {
  static const std::vector<Machine>* machines =
      new std::vector<Machine>(testing::SharedMachines());
  return *machines;
}

double WorstMm(const DeviationReport& r) { return std::max(r.max_overcut_mm, r.max_undercut_mm); }

// Brute-force deviation of `path` on [u_min, u_max] under `interpolation`
// (TCP for APT-style CL data), on a coarse grid or (`pipeline_grid`) on the
// pipeline's own, where the tolerance promise is kept (on a coarser one the
// input's worst across a move is sampled more sparsely, and its allowance
// comes out smaller).
DeviationReport Brute(const RandomCase& c, const ToolPath& path, double u_min, double u_max,
                      bool pipeline_grid = false,
                      Interpolation interpolation = Interpolation::kTcp) {
  DeviationOptions o;
  if (!pipeline_grid) {
    o.samples_u = kSamplesU;
    o.samples_v = kSamplesV;
  }
  o.u_min = u_min;
  o.u_max = u_max;
  o.interpolation = interpolation;
  DeviationReport r;
  const Status s =
      EvaluateDeviationBruteForce(c.surface, c.cutter, path, &c.machine, o, kBruteSubsteps, &r);
  EXPECT_TRUE(s.ok()) << s.message();
  return r;
}

// Peak |d2 A / ds2| and |d2 C / ds2|, rad/mm^2.
std::array<double, 2> PeakSecond(const Machine& machine, const ToolPath& path) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(machine.AssignJoints(path, &joints).ok());
  const MotionReport m = EvaluateMotion(machine, path, joints, MotionOptions());
  return {m.axes[kA].peak_second_derivative_per_mm2, m.axes[kC].peak_second_derivative_per_mm2};
}

// How far `output` is beyond the tolerance promise (solver/smooth/
// tolerance_promise.h), mm (negative: within it), by the brute-force judge
// on the pipeline's grid over [u_min, u_max] (the input's covered range);
// `*out`, if not null, receives the output's report there.
double PromiseExcessOnPipelineGridMm(const RandomCase& c, double u_min, double u_max,
                                     const ToolPath& output, DeviationReport* out = nullptr) {
  const DeviationReport in = Brute(c, c.cam_path, u_min, u_max, /*pipeline_grid=*/true);
  const DeviationReport judged = Brute(c, output, u_min, u_max, /*pipeline_grid=*/true);
  if (out != nullptr) *out = judged;
  return testing::ExcessOverTolerancePromise(c.surface, c.cam_path, in, judged,
                                             HighAccuracyOptions().tolerance_mm);
}

bool MakeCase(unsigned seed, RandomCase* c) {
  RandomCaseOptions options;
  options.poses = kPoses;
  return MakeRandomCase(seed, options, SharedMachines(), c).ok();
}

// The case of `seed`, which must fit its machine, and its input's covered
// range; a fatal failure if either is missing.
void MakeCaseOnItsRange(unsigned seed, RandomCase* c, double* u_min, double* u_max) {
  ASSERT_TRUE(MakeCase(seed, c));
  ASSERT_TRUE(c->fits_machine) << c->description;
  ASSERT_TRUE(CoveredRangeU(c->surface, c->cam_path, u_min, u_max));
}

// High accuracy as the issue's targets judge it: TCP motion (or
// `interpolation`), the input's covered range.
SmoothingSettings AsTheIssueJudges(Interpolation interpolation = Interpolation::kTcp) {
  SmoothingSettings settings;
  settings.mode = SmoothingMode::kHighAccuracy;
  settings.deviation.interpolation = interpolation;
  settings.judge_on_input_range = true;
  return settings;
}

// AsTheIssueJudges; `even_stations` off solves at the CAM's own stations,
// and `ruling_departure_factor` 0 differentiates the angles themselves (the
// mechanisms some tests below need a case of, which the defaults avoid).
Status Smooth(const RandomCase& c, SmoothingResult* result, bool even_stations = true,
              double ruling_departure_factor = HighAccuracyOptions().ruling_departure_factor) {
  SmoothingSettings settings = AsTheIssueJudges();
  settings.even_stations = even_stations;
  settings.high_accuracy.ruling_departure_factor = ruling_departure_factor;
  return testing::SmoothRandomCase(c, settings, result);
}

// The case of `seed`, which must fit its machine, smoothed; a fatal
// failure if either step fails.
void MakeAndSmooth(unsigned seed, RandomCase* c, SmoothingResult* result,
                   bool even_stations = true,
                   double ruling_departure_factor = HighAccuracyOptions().ruling_departure_factor) {
  ASSERT_TRUE(MakeCase(seed, c));
  ASSERT_TRUE(c->fits_machine) << c->description;
  const Status s = Smooth(*c, result, even_stations, ruling_departure_factor);
  ASSERT_TRUE(s.ok()) << s.message() << "\n" << c->description;
}

// What the peak d2A/ds2 and d2C/ds2 of the output are held to.
enum class D2Bound {
  // Issue 16's target: 2 x the clean SPO path's.
  kTwiceSpo,
  // The larger of that and the clean DPO path's own: for cases where the
  // accurate reference is itself beyond 2 x SPO (it passes the A = 0 pole
  // at a distance the SPO path's axis does not keep), so that the two
  // targets pull apart.
  kTwiceSpoOrDpo,
};

// Issue 16's targets on random case `seed`, smoothed and judged under
// `interpolation`: success, max |dev| <= 1.0 x the clean DPO path's by the
// brute-force judge on the input's covered range, both peak d2 within
// `d2_bound`, and every axis within the cone round its input's.
void ExpectIssueTargets(unsigned seed, D2Bound d2_bound,
                        Interpolation interpolation = Interpolation::kTcp) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(seed, &c));
  SCOPED_TRACE(c.description);
  if (!c.fits_machine) GTEST_SKIP() << "the input does not fit the machine: " << c.fit_note;
  SmoothingResult result;
  const Status s = testing::SmoothRandomCase(c, AsTheIssueJudges(interpolation), &result);
  ASSERT_TRUE(s.ok()) << s.message();

  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max, false, interpolation));
  const double out_mm = WorstMm(Brute(c, result.output, u_min, u_max, false, interpolation));
  EXPECT_LE(out_mm, 1.0 * dpo_mm) << "max |dev| " << out_mm << " mm, clean DPO " << dpo_mm
                                  << " mm";

  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  const std::array<double, 2> dpo = PeakSecond(c.machine, c.clean_dpo);
  const std::array<double, 2> out = PeakSecond(c.machine, result.output);
  if (d2_bound == D2Bound::kTwiceSpoOrDpo) {
    // Else the seed belongs with the strict target.
    EXPECT_TRUE(dpo[0] > 2.0 * spo[0] || dpo[1] > 2.0 * spo[1])
        << "the clean DPO path's peak d2A " << dpo[0] << ", d2C " << dpo[1]
        << " rad/mm^2 are within 2 x SPO's " << spo[0] << ", " << spo[1];
  }
  for (int k = 0; k < 2; ++k) {
    const double bound =
        d2_bound == D2Bound::kTwiceSpo ? 2.0 * spo[k] : std::max(2.0 * spo[k], dpo[k]);
    EXPECT_LE(out[k], bound) << "peak d2" << (k == 0 ? "A" : "C") << "/ds2 " << out[k]
                             << " rad/mm^2, SPO " << spo[k] << ", DPO " << dpo[k];
  }

  // Each output axis against the input axis of the nearest contact u.
  const std::vector<double> u_in = ProjectPathOntoRail(c.surface.rail(0), c.cam_path);
  const std::vector<double> u_out = ProjectPathOntoRail(c.surface.rail(0), result.output);
  double worst_deg = 0;
  size_t worst_pose = 0;
  for (size_t i = 0; i < result.output.poses.size(); ++i) {
    size_t nearest = 0;
    for (size_t k = 1; k < u_in.size(); ++k) {
      if (std::abs(u_in[k] - u_out[i]) < std::abs(u_in[nearest] - u_out[i])) nearest = k;
    }
    const Eigen::Vector3d& a = result.output.poses[i].a_w;
    const Eigen::Vector3d& a0 = c.cam_path.poses[nearest].a_w;
    const double deg = std::atan2(a.cross(a0).norm(), a.dot(a0)) / kDeg;
    if (deg > worst_deg) {
      worst_deg = deg;
      worst_pose = i;
    }
  }
  EXPECT_LE(worst_deg, kConeDeg) << "pose " << worst_pose << " axis " << worst_deg
                                 << " deg from its input's";
}

// A result that meets issue 16's 0.7 x target, with no run put back: max
// |dev| (brute force, on the input's covered range) within 0.7 x the clean
// DPO path's, both peak d2 within 2 x the clean SPO path's, and the
// tolerance promise kept.
void ExpectWithinSevenTenthsOfDpo(const RandomCase& c, const SmoothingResult& result) {
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  EXPECT_EQ(result.runs_kept_as_input, 0);
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max));
  EXPECT_LE(WorstMm(Brute(c, result.output, u_min, u_max)), 0.7 * dpo_mm);
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  const std::array<double, 2> out = PeakSecond(c.machine, result.output);
  EXPECT_LE(out[0], 2 * spo[0]);
  EXPECT_LE(out[1], 2 * spo[1]);
  EXPECT_LE(PromiseExcessOnPipelineGridMm(c, u_min, u_max, result.output), 0.0);
}

// Random case `seed` smoothed with the step the report counts in `taken`
// taken at least once, and within ExpectWithinSevenTenthsOfDpo.
void ExpectTakenAndWithinSevenTenthsOfDpo(unsigned seed, int SmoothingResult::*taken) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(seed, &c, &result));
  EXPECT_GE(result.*taken, 1);
  ASSERT_NO_FATAL_FAILURE(ExpectWithinSevenTenthsOfDpo(c, result));
}

class HighAccuracyRandomCasesTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(HighAccuracyRandomCasesTest, HoldsTheIssueTargets) {
  ExpectIssueTargets(GetParam(), D2Bound::kTwiceSpo);
}

// The same targets with the program smoothed and judged under joint
// interpolation (joint-style G-code's default), the DPO reference too.
class HighAccuracyRandomCasesJointTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(HighAccuracyRandomCasesJointTest, HoldsTheIssueTargetsUnderJointInterpolation) {
  ExpectIssueTargets(GetParam(), D2Bound::kTwiceSpo, Interpolation::kJoint);
}

// Under joint interpolation the axes bend to keep each move's middle on the
// surface, so a solve asked for by the flank path's peaks can need more
// than two stiffer solves in turn (SmoothingSettings::stiffer_solves).
// Seed 20 at the program's own move count (no split for the joint bow):
// after two, peak d2A/ds2 stays at 11 x the clean SPO path's (the
// benchmark's judge); after up to four, within 2 x.
TEST(HighAccuracyRandomCasesTest, UnderJointInterpolationTwoStifferSolvesLeaveTheAxesRough) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(20, &c));
  ASSERT_TRUE(c.fits_machine) << c.description;
  SmoothingSettings settings = AsTheIssueJudges(Interpolation::kJoint);
  settings.split_moves_for_tolerance = 1;
  settings.stiffer_solves = 2;
  SmoothingResult two;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &two).ok());
  EXPECT_EQ(two.stiffer_solves, 2);
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  EXPECT_GT(PeakSecond(c.machine, two.output)[0], 2 * spo[0]);
  settings.stiffer_solves = SmoothingSettings().stiffer_solves;
  SmoothingResult more;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &more).ok());
  EXPECT_GT(more.stiffer_solves, 2);
  EXPECT_LE(PeakSecond(c.machine, more.output)[0], 2 * spo[0]);
}

// Under joint interpolation a smooth path at the program's pose count can
// miss points the programmed moves happened to cut exactly: seed 146's
// solves leave points beyond the tolerance there, and its run goes back as
// programmed. Its programmed moves bow off their line by more than half the
// tolerance, so by default each cutting move is split before the solve
// (SmoothingSettings::split_moves_for_tolerance), and the solve holds them:
// the output has new poses between the program's (the leads are not
// split), and by the brute-force judge on the pipeline's grid no point
// beyond the tolerance promise.
TEST(HighAccuracyRandomCasesTest, UnderJointInterpolationSplitMovesHoldTheTolerance) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(146, &c));
  ASSERT_TRUE(c.fits_machine) << c.description;
  SmoothingSettings settings = AsTheIssueJudges(Interpolation::kJoint);
  settings.split_moves_for_tolerance = 1;
  SmoothingResult unsplit;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &unsplit).ok());
  EXPECT_EQ(unsplit.moves_per_move, 1);
  ASSERT_EQ(unsplit.runs_kept.size(), 1u);
  EXPECT_EQ(unsplit.runs_kept[0].reason, "tolerance");
  EXPECT_EQ(unsplit.output.poses.size(), c.cam_path.poses.size());

  settings.split_moves_for_tolerance = SmoothingSettings().split_moves_for_tolerance;
  SmoothingResult split;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &split).ok());
  EXPECT_GE(split.moves_per_move, 2);
  EXPECT_GT(split.input_joint_bow_mm, 0.5 * HighAccuracyOptions().tolerance_mm);
  EXPECT_EQ(split.runs_kept_as_input, 0);
  EXPECT_GT(split.output.poses.size(), c.cam_path.poses.size());
  EXPECT_LT(split.output.poses.size(), split.moves_per_move * c.cam_path.poses.size());
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const DeviationReport in = Brute(c, c.cam_path, u_min, u_max, true, Interpolation::kJoint);
  const DeviationReport out = Brute(c, split.output, u_min, u_max, true, Interpolation::kJoint);
  EXPECT_LE(testing::ExcessOverTolerancePromise(c.surface, c.cam_path, in, out,
                                                HighAccuracyOptions().tolerance_mm),
            0.0);
}

// Under joint interpolation seed 116's programmed moves bow off their line
// by far more than half the tolerance: solved at the program's own move
// count the output stays beyond half the clean DPO path's max |dev| (the
// DPO path's moves bow too; beyond all of it before stop 52's capped step,
// 0.84 x since), and split for the bow (into four, the most
// SmoothingSettings::split_moves_for_tolerance allows by default) it comes
// within a fifth of it, by the brute-force judge.
TEST(HighAccuracyRandomCasesTest, UnderJointInterpolationTheMovesAreSplitForTheirBow) {
  RandomCase c;
  double u_min = 0, u_max = 0;
  ASSERT_NO_FATAL_FAILURE(MakeCaseOnItsRange(116, &c, &u_min, &u_max));
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max, false, Interpolation::kJoint));
  SmoothingSettings settings = AsTheIssueJudges(Interpolation::kJoint);
  settings.split_moves_for_tolerance = 1;
  SmoothingResult unsplit;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &unsplit).ok());
  EXPECT_EQ(unsplit.moves_per_move, 1);
  EXPECT_EQ(unsplit.input_joint_bow_mm, 0.0);
  EXPECT_GT(WorstMm(Brute(c, unsplit.output, u_min, u_max, false, Interpolation::kJoint)),
            0.5 * dpo_mm);

  settings.split_moves_for_tolerance = SmoothingSettings().split_moves_for_tolerance;
  SmoothingResult split;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &split).ok());
  EXPECT_EQ(split.moves_per_move, 4);
  // (Split in two it would still bow by more than half the tolerance.)
  EXPECT_GT(split.input_joint_bow_mm, 4 * 0.5 * HighAccuracyOptions().tolerance_mm);
  EXPECT_EQ(split.runs_kept_as_input, 0);
  EXPECT_LT(WorstMm(Brute(c, split.output, u_min, u_max, false, Interpolation::kJoint)),
            0.2 * dpo_mm);
}

// Cases whose clean DPO path is itself beyond 2 x the SPO path's peak d2.
class HighAccuracyRandomCasesRoughReferenceTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(HighAccuracyRandomCasesRoughReferenceTest, HoldsTheTargetsWithD2NoWorseThanTheDpoPath) {
  ExpectIssueTargets(GetParam(), D2Bound::kTwiceSpoOrDpo);
}

// Where every solve leaves grid points beyond the tolerance that the input
// held across the moves that cut them (the first, and the retries from the
// other start and with the held points guarded inside the moves; seed 143:
// 0.0138 mm at u 0.111, v 0.3, where the input left 0.0121 mm), the runs
// that reach them go back as programmed instead of the path being refused
// (issue 17's rule: no refusal for what the input did not do). The
// brute-force judge then finds no point beyond both the tolerance and the
// input's allowance (solver/smooth/tolerance_promise.h). (Seeds 33 and 57,
// this test's cases at stop 24, are now kept by a retry; so is seed 20,
// since the guard rulings at the rulings' ends, stop 30: see below.) At
// the CAM's own stations (and so without split moves, which are placed at
// even stations): at even stations the seed keeps its solve.
TEST(HighAccuracyRandomCasesPutBackTest, RunsGoBackWhereTheToleranceRoundsLeavePointsBeyond) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(143, &c, &result, /*even_stations=*/false));
  EXPECT_GT(result.runs_kept_as_input, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const DeviationReport in = Brute(c, c.cam_path, u_min, u_max);
  const DeviationReport out = Brute(c, result.output, u_min, u_max);
  ASSERT_EQ(in.deviation_mm.size(), out.deviation_mm.size());
  const std::vector<double> allowance =
      InputAllowance(in, CuttingContactU(c.surface, c.cam_path));
  const double tolerance_mm = HighAccuracyOptions().tolerance_mm;
  for (size_t k = 0; k < out.deviation_mm.size(); ++k) {
    const double d = std::abs(out.deviation_mm[k]);
    EXPECT_TRUE(d <= tolerance_mm || d <= allowance[k] + 1e-6)
        << "grid point " << k << ": " << d << " mm, input " << in.deviation_mm[k]
        << " mm, allowance " << allowance[k] << " mm";
  }
}

// A solve kept at the CAM's own stations holds the promise on the
// pipeline's grid (200 x 21 over the input's range), to the brute-force
// judge's 40 steps a move. It is a promise at those points only: a finer
// grid can find more between them (seed 20, this test's case from stop 30
// to stop 40: this file's 60 x 7 grid found 0.0116 mm at a ruling's end,
// where the input left 0.0005 mm), so the test bounds that gap at 3 um
// beyond the promise, so that it cannot grow unseen. Seed 22 keeps its
// solve at these stations. (Since stop 41's guards seed 20 puts a run back
// at them; at even stations, the default, it holds the issue's targets.)
TEST(HighAccuracyRandomCasesPutBackTest, AKeptSolveHoldsThePromiseOnThePipelinesGrid) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(22, &c, &result, /*even_stations=*/false));
  EXPECT_EQ(result.runs_kept_as_input, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  EXPECT_LE(PromiseExcessOnPipelineGridMm(c, u_min, u_max, result.output), 1e-4);
  EXPECT_LE(testing::ExcessOverTolerancePromise(c.surface, c.cam_path,
                                                Brute(c, c.cam_path, u_min, u_max),
                                                Brute(c, result.output, u_min, u_max),
                                                HighAccuracyOptions().tolerance_mm),
            0.003);
}

// Seed 57 (overhang 2.8 mm; the input exact along the floor): the first
// solve left the foot of the u = 1 end ruling 0.0145 mm into the surface
// through four tolerance rounds, and its run went back with the input's
// 6.7 x the clean DPO path's max |dev|. Solved again (from the other start,
// then with the held points guarded inside the moves near them) it keeps
// the promise, so the solve is kept: the brute-force judge finds it within
// the clean DPO path's max |dev| and its peaks d2 within 2 x the clean SPO
// path's. At the CAM's own stations, and with the angles themselves
// differentiated: at even stations the first solve keeps the promise, and
// differentiating the departure from the rulings, d2C/ds2 comes out at
// 3.6 x SPO at the CAM's stations (0.56 x at even stations).
TEST(HighAccuracyRandomCasesPutBackTest, ASolveLeftBeyondTheToleranceIsTriedAgainBeforeItGoesBack) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(57, &c, &result, /*even_stations=*/false,
                                        /*ruling_departure_factor=*/0));
  EXPECT_EQ(result.runs_kept_as_input, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  DeviationReport out;
  EXPECT_LE(PromiseExcessOnPipelineGridMm(c, u_min, u_max, result.output, &out), 1e-3);
  EXPECT_LE(WorstMm(out), WorstMm(Brute(c, c.clean_dpo, u_min, u_max, /*pipeline_grid=*/true)));
  const std::array<double, 2> smoothed = PeakSecond(c.machine, result.output);
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  EXPECT_LE(smoothed[0], 2 * spo[0]);
  EXPECT_LE(smoothed[1], 2 * spo[1]);
}

// Seed 46 (near the pole; the input exact along the floor): a point of the
// floor the solve gouged from a neighbouring pose stayed 0.0119 mm beyond
// the tolerance through four rounds at up to 1000 times the surface's
// weight, and the whole run went back with the input's 0.87 mm, because a
// held point was held only on the move whose rulings bracket it. Held also
// as a guard at the poses within reach, it is mended in the rounds: the
// solve is kept, and the brute-force judge finds the promise kept.
TEST(HighAccuracyRandomCasesPutBackTest, APointGougedFromANeighbouringPoseIsHeldToTheTolerance) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(46, &c, &result));
  EXPECT_EQ(result.runs_kept_as_input, 0);
  EXPECT_GT(result.tolerance_rounds, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const DeviationReport in = Brute(c, c.cam_path, u_min, u_max);
  const DeviationReport out = Brute(c, result.output, u_min, u_max);
  // The brute force samples each move more finely than the pipeline's judge.
  EXPECT_LE(testing::ExcessOverTolerancePromise(c.surface, c.cam_path, in, out,
                                                HighAccuracyOptions().tolerance_mm),
            1e-3);
  EXPECT_LT(WorstMm(out), 0.5 * WorstMm(in));
}

// Seed 120 under joint interpolation: the solve at even stations moved a
// pose out of the travel (Z -175 mm against [-120, 120]) and was refused;
// it is solved again at the program's own stations, which the input fits,
// so the case succeeds inside the travel. (With the angles themselves
// differentiated, one deviation check inside each move and the end-of-cut
// guards at the held point's full weight: differentiating their departure
// from the rulings, with two checks, or with the guards at their default
// weight, the solve at even stations keeps inside the travel.)
TEST(HighAccuracyRandomCasesTest, ASolveRefusedAtEvenStationsIsSolvedAtTheProgramsOwn) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(120, &c));
  ASSERT_TRUE(c.fits_machine) << c.description;
  SmoothingSettings settings;
  settings.mode = SmoothingMode::kHighAccuracy;
  settings.high_accuracy.ruling_departure_factor = 0;
  settings.high_accuracy.between_samples = 1;
  settings.high_accuracy.end_of_cut_guard_weight = 1;
  settings.deviation.interpolation = Interpolation::kJoint;
  settings.judge_on_input_range = true;
  SmoothingResult result;
  const Status s = testing::SmoothRandomCase(c, settings, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_FALSE(result.even_stations);
  std::vector<JointVector> joints;
  ASSERT_TRUE(c.machine.AssignJoints(result.output, &joints).ok());
  EXPECT_TRUE(c.machine.CheckTravel(result.output, joints).ok());
}

// Seed 14 writes three pairs of poses 1 micrometre apart. Each second pose
// of a pair is placed on the solved move across it (the controller's TCP
// move between its neighbours), not solved on its own, where its last-digit
// disagreement with its twin gave the peak d2C/ds2 of the whole path
// (0.34 deg/mm^2 at a 2.6 um step; 0.055 now). At the CAM's own stations:
// even stations leave no micrometre step inside a stretch.
TEST(HighAccuracyRandomCasesTest, AMicrometreStepLiesOnTheSolvedMoveAcrossIt) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(14, &c, &result, /*even_stations=*/false));
  const ToolPath& in = c.cam_path;
  const ToolPath& out = result.output;
  std::vector<JointVector> joints;
  ASSERT_TRUE(c.machine.AssignJoints(out, &joints).ok());
  int steps = 0;
  for (size_t i = 1; i + 1 < in.poses.size(); ++i) {
    const double step = (in.poses[i].p_w_tip - in.poses[i - 1].p_w_tip).norm();
    if (step > 2e-3) continue;
    ++steps;
    // Pose i at its input fraction of the move from i - 1 to i + 1.
    const double lambda = step / (in.poses[i + 1].p_w_tip - in.poses[i - 1].p_w_tip).norm();
    Eigen::Vector3d tip, axis;
    InterpolateMove<double>(c.machine.kinematics, Interpolation::kTcp, joints[i - 1],
                            joints[i + 1], out.poses[i - 1].p_w_tip, out.poses[i + 1].p_w_tip,
                            lambda, &tip, &axis);
    EXPECT_LT((tip - out.poses[i].p_w_tip).norm(), 1e-9) << "pose " << i;
    EXPECT_LT((axis - out.poses[i].a_w).norm(), 1e-9) << "pose " << i;
  }
  EXPECT_EQ(steps, 3);
  EXPECT_LT(PeakSecond(c.machine, out)[1], 0.15 * kDeg);
}

// Seed 42 leads in with two poses 1.8 mm apart beyond the surface's u = 0
// end. Tied to the end ruling like the pose that cuts it, they were pulled
// along onto it (3.2 mm), their cut against the end pose shrinking to a
// tenth of a millimetre and its peak d2A/ds2 of 0.6 deg/mm^2 the path's.
// Now they keep within 1 mm of their programmed line, the approach keeps
// its length, and the cut is no farther from the surface.
TEST(HighAccuracyRandomCasesTest, ALeadInKeepsItsLineAndLength) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(42, &c, &result));
  const ToolPath& in = c.cam_path;
  const ToolPath& out = result.output;
  ASSERT_EQ(c.parameters.lead_in_poses, 2);
  const Eigen::Vector3d line = (in.poses[2].p_w_tip - in.poses[0].p_w_tip).normalized();
  for (size_t i = 0; i < 2; ++i) {
    const Eigen::Vector3d off = out.poses[i].p_w_tip - in.poses[i].p_w_tip;
    EXPECT_LE((off - off.dot(line) * line).norm(), 1.0 + 1e-3) << "lead-in pose " << i;
  }
  const double programmed = (in.poses[2].p_w_tip - in.poses[0].p_w_tip).norm();
  EXPECT_GT((out.poses[2].p_w_tip - out.poses[0].p_w_tip).norm(), 0.8 * programmed);
  EXPECT_LT(PeakSecond(c.machine, out)[0], 0.1 * kDeg);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, in, &u_min, &u_max));
  EXPECT_LT(WorstMm(Brute(c, out, u_min, u_max)), 0.5 * WorstMm(Brute(c, c.clean_dpo, u_min, u_max)));
}

// Seed 20 leads in with three poses beyond the surface's u = 0 end, which
// CAM writes with the end pose's axis: the rotary axes stood still until
// the cut, and its junction was the path's peak d2A/ds2 (89 x the clean SPO
// path's; the lead-in had also started on the other branch of A from the
// solve's). The leads' axes now continue the cut's rotary motion
// (solver/smooth/lead_continuation.h), and no pose of a lead or at its
// junction bends A or C more than the cut does elsewhere.
TEST(HighAccuracyRandomCasesTest, ALeadContinuesTheCutsRotaryMotion) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(20, &c, &result));
  ASSERT_EQ(c.parameters.lead_in_poses, 3);
  ASSERT_EQ(c.parameters.lead_out_poses, 2);
  EXPECT_EQ(result.lead_poses_continued, 5);
  const ToolPath& out = result.output;
  std::vector<JointVector> joints;
  ASSERT_TRUE(c.machine.AssignJoints(out, &joints).ok());
  const MotionSamples m = ComputeMotionSamples(c.machine, out, joints, 1000);
  const size_t n = out.poses.size();
  for (int axis : {kA, kC}) {
    double leads = 0, cut = 0;
    for (size_t i = 1; i + 1 < n; ++i) {
      const double d2 = SecondDerivativePerMm2(out, joints, m, i, axis);
      (i <= 3 || i + 3 >= n ? leads : cut) = std::max(i <= 3 || i + 3 >= n ? leads : cut, d2);
    }
    EXPECT_LE(leads, cut) << (axis == kA ? "A" : "C");
  }
}

// Where the solve makes a run worse on peak d2 than the input's, it is
// solved again from its result with the smoothness weights raised before
// the never-worse rule would put the input's run back (with the input's
// deviation). Seed 138 of the benchmark: one stiffer solve, no run put
// back, 0.15 x the clean DPO path's max |dev|. (Seed 127, this test's case
// at stop 27, needs none with two deviation checks inside each move.) (Seed 30, this test's case
// at stop 23, needs no stiffer solve since stop 24's lead-ins.)
TEST(HighAccuracyRandomCasesPutBackTest, AStifferSolveKeepsTheRunInsteadOfPuttingTheInputBack) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(138u, &c, &result));
  EXPECT_GE(result.stiffer_solves, 1);
  EXPECT_EQ(result.runs_kept_as_input, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max));
  EXPECT_LE(WorstMm(Brute(c, result.output, u_min, u_max)), 0.7 * dpo_mm);
  const std::array<double, 2> in = PeakSecond(c.machine, c.cam_path);
  const std::array<double, 2> out = PeakSecond(c.machine, result.output);
  EXPECT_LE(out[0], in[0]);
  EXPECT_LE(out[1], in[1]);
}

// A run the CAM program leaves beyond the tolerance is not put back as
// programmed for being a little rougher than programmed, where it stays
// within stiffer_above_flank_d2 x the surface's own flank path's peak d2
// (SmoothingSettings::keep_runs_no_worse): put back, it would be out of
// tolerance again. Seed 134 of the benchmark: its one run passes the A = 0
// pole with peak d2C at 1.47 x the clean SPO path's, 5.1 x the clean DPO
// path's max |dev| off; the solve passes nearer the pole, rougher on C,
// and until stop 38 its run went back after two stiffer solves.
TEST(HighAccuracyRandomCasesPutBackTest,
     ARunProgrammedBeyondTheToleranceMayBeRougherThanProgrammed) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(134u, &c, &result));
  EXPECT_EQ(result.runs_kept_as_input, 0);
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  EXPECT_GT(WorstMm(Brute(c, c.cam_path, u_min, u_max)), HighAccuracyOptions().tolerance_mm);
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max));
  EXPECT_LE(WorstMm(Brute(c, result.output, u_min, u_max)), 0.7 * dpo_mm);
  const std::array<double, 2> in = PeakSecond(c.machine, c.cam_path);
  const std::array<double, 2> out = PeakSecond(c.machine, result.output);
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  // Rougher than programmed on C (what the rule's exception is for), and
  // within the issue's 2 x SPO on both axes.
  EXPECT_GT(out[1], in[1]);
  EXPECT_LE(out[0], 2.0 * spo[0]);
  EXPECT_LE(out[1], 2.0 * spo[1]);
  // The result says so: the one run, its peaks, and how far off the
  // programmed run is (the pipeline's grid, finer than Brute's here).
  ASSERT_EQ(result.runs_rougher.size(), 1u);
  const RougherRun& rougher = result.runs_rougher[0];
  EXPECT_EQ(rougher.axis, "C");
  EXPECT_NEAR(rougher.input_peak, in[1], 1e-9 * in[1]);
  EXPECT_NEAR(rougher.smoothed_peak, out[1], 1e-9 * out[1]);
  EXPECT_GT(rougher.input_worst_mm, HighAccuracyOptions().tolerance_mm);
  EXPECT_LE(rougher.input_worst_mm, WorstMm(*result.input_metrics.deviation));
  EXPECT_LE(PromiseExcessOnPipelineGridMm(c, u_min, u_max, result.output), 0.0);
  // And so does the report, in degrees.
  const nlohmann::json report = SmoothReportJson({"test"}, "high_accuracy", result);
  ASSERT_EQ(report["runs_rougher_than_programmed"].size(), 1u);
  const nlohmann::json& listed = report["runs_rougher_than_programmed"][0];
  EXPECT_EQ(listed["axis"], "C");
  EXPECT_NEAR(listed["input_peak_d2_deg_per_mm2"].get<double>(), in[1] / kDeg, 1e-9);
  EXPECT_NEAR(listed["smoothed_peak_d2_deg_per_mm2"].get<double>(), out[1] / kDeg, 1e-9);
  EXPECT_EQ(listed["input_worst_mm"].get<double>(), rougher.input_worst_mm);
  EXPECT_EQ(report["runs_kept_as_input"], 0);
}

// That exception is the never-worse rule's only one. On the same case with
// accept_over_tolerance (no promise held) or with a tolerance the
// programmed run keeps, the run comes out no rougher than programmed on
// either axis.
TEST(HighAccuracyRandomCasesPutBackTest, ARunIsNoRougherThanProgrammedOutsideTheException) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(134u, &c));
  ASSERT_TRUE(c.fits_machine) << c.description;
  const std::array<double, 2> in = PeakSecond(c.machine, c.cam_path);
  SmoothingSettings accepted = AsTheIssueJudges();
  accepted.accept_over_tolerance = true;
  SmoothingSettings loose = AsTheIssueJudges();
  loose.high_accuracy.tolerance_mm = 1.0;
  for (const SmoothingSettings& settings : {accepted, loose}) {
    SCOPED_TRACE(settings.accept_over_tolerance ? "accept_over_tolerance" : "tolerance 1 mm");
    SmoothingResult result;
    const Status s = testing::SmoothRandomCase(c, settings, &result);
    ASSERT_TRUE(s.ok()) << s.message();
    if (!settings.accept_over_tolerance) {
      ASSERT_LT(WorstMm(*result.input_metrics.deviation), settings.high_accuracy.tolerance_mm);
    }
    EXPECT_TRUE(result.runs_rougher.empty());
    const std::array<double, 2> out = PeakSecond(c.machine, result.output);
    EXPECT_LE(out[0], in[0] + 1e-9);
    EXPECT_LE(out[1], in[1] + 1e-9);
  }
}

// Where the solve's axes accelerate more than twice as hard as the
// surface's own flank path's (SmoothingSettings::stiffer_above_flank_d2),
// it is solved again stiffer. Seed 91 of the benchmark: its solve left peak
// d2A/ds2 at 27 x the clean SPO path's, within the tolerance and never worse
// than the input's, so no other rule asked for more; solved stiffer, both
// peaks hold within 2 x SPO, at a quarter of the clean DPO path's max |dev|.
TEST(HighAccuracyRandomCasesPutBackTest, AxesRougherThanTheSurfacesOwnFlankPathAreSolvedStiffer) {
  RandomCase c;
  double u_min = 0, u_max = 0;
  ASSERT_NO_FATAL_FAILURE(MakeCaseOnItsRange(91, &c, &u_min, &u_max));
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max));
  SmoothingSettings settings = AsTheIssueJudges();
  settings.stiffer_above_flank_d2 = 0;
  SmoothingResult rough;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &rough).ok());
  EXPECT_EQ(rough.stiffer_solves, 0);
  EXPECT_GT(PeakSecond(c.machine, rough.output)[0], 2 * spo[0]);
  settings.stiffer_above_flank_d2 = SmoothingSettings().stiffer_above_flank_d2;
  SmoothingResult result;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &result).ok());
  EXPECT_GE(result.stiffer_solves, 1);
  EXPECT_EQ(result.runs_kept_as_input, 0);
  const std::array<double, 2> out = PeakSecond(c.machine, result.output);
  EXPECT_LE(out[0], 2 * spo[0]);
  EXPECT_LE(out[1], 2 * spo[1]);
  EXPECT_LE(WorstMm(Brute(c, result.output, u_min, u_max)), 0.7 * dpo_mm);
}

// The report says how rough the written path is against the surface's own
// flank path, and where. Seed 91 solved with no stiffer step ends with peak
// d2A/ds2 beyond 2 x the clean SPO path's; the ratio, its axis and its line
// are checked against a flank path generated here and a scan of the output.
TEST(HighAccuracyRandomCasesTest, TheReportGivesThePeakD2OverTheSurfacesOwnFlankPath) {
  RandomCase c;
  double u_min = 0, u_max = 0;
  ASSERT_NO_FATAL_FAILURE(MakeCaseOnItsRange(91, &c, &u_min, &u_max));
  constexpr int kFirstLine = 100;
  for (size_t i = 0; i < c.cam_path.poses.size(); ++i) {
    c.cam_path.poses[i].source_line = kFirstLine + static_cast<int>(i);
  }
  SmoothingSettings settings = AsTheIssueJudges();
  settings.stiffer_above_flank_d2 = 0;
  SmoothingResult result;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &result).ok());
  const FlankRoughness& r = result.flank_roughness;
  ASSERT_TRUE(r.measured);
  FlankPathOptions flank_options;
  flank_options.cutter_radius_mm = c.cutter.radius_mm;
  flank_options.taper_rad = c.cutter.taper_rad;
  flank_options.poses = static_cast<int>(c.cam_path.poses.size());
  ToolPath flank;
  ASSERT_TRUE(GenerateFlankPath(c.surface, flank_options, &flank).ok());
  const std::array<double, 2> flank_peak = PeakSecond(c.machine, flank);
  const std::array<double, 2> out_peak = PeakSecond(c.machine, result.output);
  const std::array<double, 2> ratio = {out_peak[0] / flank_peak[0], out_peak[1] / flank_peak[1]};
  const int axis = ratio[0] >= ratio[1] ? 0 : 1;
  EXPECT_EQ(r.axis, axis == 0 ? "A" : "C");
  EXPECT_NEAR(r.Ratio(), ratio[axis], 1e-9 * ratio[axis]);
  EXPECT_GT(r.Ratio(), 2.0);
  std::vector<JointVector> joints;
  ASSERT_TRUE(c.machine.AssignJoints(result.output, &joints).ok());
  const MotionSamples m =
      ComputeMotionSamples(c.machine, result.output, joints, settings.feed.default_feed_mm_per_min);
  std::vector<int> lines_at_peak;
  for (size_t i = 0; i < result.output.poses.size(); ++i) {
    if (SecondDerivativePerMm2(result.output, joints, m, i, axis == 0 ? kA : kC) ==
        out_peak[axis]) {
      lines_at_peak.push_back(result.output.poses[i].source_line);
    }
  }
  ASSERT_EQ(lines_at_peak.size(), 1u);
  EXPECT_EQ(r.line, lines_at_peak[0]);
  EXPECT_GE(r.line, kFirstLine);
  const nlohmann::json report = SmoothReportJson({"test"}, "high_accuracy", result);
  EXPECT_EQ(report["peak_d2_over_flank_path"]["line"], r.line);
  EXPECT_NEAR(report["peak_d2_over_flank_path"]["flank_path_peak_d2_deg_per_mm2"].get<double>(),
              flank_peak[axis] * 180 / M_PI, 1e-9 * flank_peak[axis] * 180 / M_PI);
}

// The ten-fold stiffer steps spent on a path still rougher than the flank
// path's peaks allow, one step more at the weights as they were caps the
// axes' peak d2 instead (SmoothingSettings::peak_d2_cap_over_flank,
// solver/smooth/cost/peak_second_cost.h). Seed 42 of the benchmark: after
// four ten-fold steps its peak d2A/ds2 stays at 8.6 x the clean SPO path's;
// capped, within 2 x and 0.7 x the clean DPO path's max |dev|, the tolerance
// promise kept.
TEST(HighAccuracyRandomCasesTest, AStepWithThePeaksCappedFollowsTheTenFoldSteps) {
  RandomCase c;
  double u_min = 0, u_max = 0;
  ASSERT_NO_FATAL_FAILURE(MakeCaseOnItsRange(42, &c, &u_min, &u_max));
  const std::array<double, 2> spo = PeakSecond(c.machine, c.clean_spo);
  SmoothingSettings settings = AsTheIssueJudges();
  settings.peak_d2_cap_over_flank = 0;
  SmoothingResult ten_fold;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &ten_fold).ok());
  EXPECT_EQ(ten_fold.stiffer_solves_capped, 0);
  EXPECT_EQ(ten_fold.stiffer_solves, settings.stiffer_solves);
  EXPECT_GT(PeakSecond(c.machine, ten_fold.output)[0], 4 * spo[0]);
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(42, &c, &result));
  EXPECT_EQ(result.stiffer_solves_capped, 1);
  ASSERT_NO_FATAL_FAILURE(ExpectWithinSevenTenthsOfDpo(c, result));
}

// Seeds whose cases hold the targets (11 and 15 since stop 24; 2, 4, 5, 10,
// 13 and 14 since the solve's even stations, stop 26; 8 again since its
// lead-out continues the cut's motion, stop 28; 9 since axes rougher than
// the surface's flank path are solved stiffer, stop 29; 3, 12, 16, 18, 19
// and 20 since the guard rulings at 0.15 mm at the rulings' ends, stop 30).
// Least squares leaves the deviation's peak where the smoothness and the
// surface disagree most; the peak-deviation rounds (SmoothingSettings::
// peak_deviation_rounds) hold the grid points beyond half of it (or 0.7
// of it) lower.
// Seed 66 of the benchmark: without them its worst point is 1.3 x the
// clean DPO path's max |dev|; with them below 0.7 x, both peak d2 within
// 2 x the clean SPO path's and the tolerance promise kept.
TEST(HighAccuracyRandomCasesTest, PeakDeviationRoundsLowerTheWorstPoint) {
  RandomCase c;
  ASSERT_TRUE(MakeCase(66, &c));
  ASSERT_TRUE(c.fits_machine) << c.description;
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(c.surface, c.cam_path, &u_min, &u_max));
  const double dpo_mm = WorstMm(Brute(c, c.clean_dpo, u_min, u_max));
  SmoothingSettings settings = AsTheIssueJudges();
  settings.peak_deviation_rounds = 0;
  SmoothingResult without;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &without).ok());
  EXPECT_EQ(without.peak_deviation_rounds, 0);
  const double without_mm = WorstMm(Brute(c, without.output, u_min, u_max));
  EXPECT_GT(without_mm, dpo_mm);
  settings.peak_deviation_rounds = SmoothingSettings().peak_deviation_rounds;
  SmoothingResult result;
  ASSERT_TRUE(testing::SmoothRandomCase(c, settings, &result).ok());
  EXPECT_GE(result.peak_deviation_rounds, 1);
  ASSERT_NO_FATAL_FAILURE(ExpectWithinSevenTenthsOfDpo(c, result));
}

// A stiffer solve raises the smoothness weights ten-fold at once, and the
// path it ends on can be far smoother than asked and farther off the
// surface than need be; the last step is eased back towards the result
// before it (SolveStiffer, LowerPeaksOfStifferOrEased). Seed 113 of the
// benchmark: stiff, 0.75 x the clean DPO path's max |dev| with peak d2
// 1.5 x the clean SPO path's; eased, below 0.7 x with both still within
// 2 x and the tolerance promise kept.
TEST(HighAccuracyRandomCasesTest, TheLastStifferStepIsEasedBackWhereThatIsNearerTheSurface) {
  RandomCase c;
  SmoothingResult result;
  ASSERT_NO_FATAL_FAILURE(MakeAndSmooth(113, &c, &result));
  EXPECT_GE(result.stiffer_solves, 1);
  EXPECT_EQ(result.stiffer_solves_eased, 1);
  ASSERT_NO_FATAL_FAILURE(ExpectWithinSevenTenthsOfDpo(c, result));
}

// Held at half the worst deviation, a peak round's points can pull the
// solve's axes 5-21 x as hard as the flank path's, and every blend of it
// is refused; the round is then tried with the points held at 0.7 of the
// worst (LowerPeakDeviation). Seeds 74, 136 and 198 of the benchmark: at
// half alone no round was taken and they ended at 0.74, 0.77 and 0.77 x
// the clean DPO path's max |dev| (the benchmark's judge); now a round is
// taken at 0.7, and they end below 0.7 x (this test's brute-force judge;
// 74 was below it there already, at half alone), both peak d2 within 2 x
// the clean SPO path's and the tolerance promise kept.
class PeakRoundAtAMilderBoundTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(PeakRoundAtAMilderBoundTest, IsTakenWhereTheRoundAtHalfTheWorstIsRefused) {
  ExpectTakenAndWithinSevenTenthsOfDpo(GetParam(), &SmoothingResult::peak_rounds_at_milder_bound);
}

INSTANTIATE_TEST_SUITE_P(RandomCases, PeakRoundAtAMilderBoundTest,
                         ::testing::Values(74u, 136u, 198u));

// A stiffer solve whose tips slide along the path can bend the axes harder
// as the controller turns them (over the tips' arc length) while its
// stencils, over the stations', see them smoother; from both starts it
// came out rougher and was refused. It is then solved again with each tip
// held along the path where the solve starts it (SolveStiffer,
// solver/smooth/cost/tip_slide_cost.h).
// Seeds 60, 80 and 160 of the benchmark: with free tips left at peak d2A
// 2.01, 2.01 and 10.9 x the clean SPO path's (the benchmark's judge); with
// the tips held, within 2 x (1.69, 1.71 and 1.22 x there) and 0.7 x the
// clean DPO path's max |dev|, the tolerance promise kept.
class StifferSolveWithTheTipsHeldTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(StifferSolveWithTheTipsHeldTest, HoldsTheTipsWhereTheFreeTipsCameOutRougher) {
  ExpectTakenAndWithinSevenTenthsOfDpo(GetParam(), &SmoothingResult::stiffer_solves_tips_held);
}

INSTANTIATE_TEST_SUITE_P(RandomCases, StifferSolveWithTheTipsHeldTest,
                         ::testing::Values(60u, 80u, 160u));

INSTANTIATE_TEST_SUITE_P(Passing, HighAccuracyRandomCasesTest,
                         ::testing::Values(2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 10u, 11u, 12u, 13u,
                                           14u, 15u, 16u, 17u, 18u, 19u, 20u, 21u, 22u, 23u,
                                           24u));

// Seeds that hold the targets only since a stiffer solve also starts from
// the first solve's start (stop 34; from its own result alone: 57 at 1.64 x
// the clean DPO path's max |dev|, 130 at 4.8 x with its run put back as
// programmed, 199 at 3.7 x the clean SPO path's peak d2C).
INSTANTIATE_TEST_SUITE_P(StifferFromTheFirstStart, HighAccuracyRandomCasesTest,
                         ::testing::Values(57u, 130u, 199u));

// Seeds that hold the targets only since a stiffer solve weighs the tip's
// d2 at 10 mm^2 or more (stop 35; at 0.01 x 10 each fails here, checked:
// 75 at d2A 3.4 x and d2C 2.6 x the clean SPO path's, 196 at d2A 3.7 x).
INSTANTIATE_TEST_SUITE_P(StifferTipPath, HighAccuracyRandomCasesTest,
                         ::testing::Values(75u, 196u));

// Seeds that hold the targets only since a stiffer solve holds A to its
// ruling's A near the pole too (stop 36; without it, measured here: 68 at
// d2A 2.86 x the clean SPO path's, 116 at d2A 2.84 x, 174 at 1.14 x the
// clean DPO path's max |dev|, d2A 23 x and d2C 4.9 x, 197 at d2A 2.11 x).
INSTANTIATE_TEST_SUITE_P(StifferAReferenceNearThePole, HighAccuracyRandomCasesTest,
                         ::testing::Values(68u, 116u, 174u, 197u));

// Seeds that hold the targets only since a stiffer solve is asked for above
// 1.8 x the pipeline's flank path's peak d2, not 2 x (stop 36; at 2 x,
// measured here: 82 at d2C 2.16 x the clean SPO path's, 102 at d2C 2.00 x).
INSTANTIATE_TEST_SUITE_P(StifferTriggerMargin, HighAccuracyRandomCasesTest,
                         ::testing::Values(82u, 102u));

// Seeds that hold the targets only since a run programmed beyond the
// tolerance may come out rougher than programmed within 1.8 x the flank
// path's peak d2 (stop 38; before, it went back as programmed, measured by
// the benchmark: 108 at 5.1 x the clean DPO path's max |dev| and d2A 3.2 x
// the clean SPO path's). Seed 134 (5.1 x, d2A 5.1 x before) is the test
// above.
INSTANTIATE_TEST_SUITE_P(RougherThanProgrammed, HighAccuracyRandomCasesTest,
                         ::testing::Values(108u));

// Joint interpolation: seeds that hold the targets only since stop 39's
// stiffer solves, up to four in turn (two before: d2A 11 x, d2C 9.0 x and
// d2A 4.1 x the clean SPO path's).
INSTANTIATE_TEST_SUITE_P(MoreStifferSolves, HighAccuracyRandomCasesJointTest,
                         ::testing::Values(20u, 109u, 196u));

// Joint interpolation: seeds that hold the targets only since stop 40's
// split moves; at the program's own move count the solve left points
// beyond the tolerance that the input's moves held, and the run went back
// as programmed (measured by the benchmark: 88 at 2.0 x the clean DPO
// path's max |dev|, 146 at 4.9 x; 175, at 5.9 x before, held from stop 40
// to stop 41 and is below).
INSTANTIATE_TEST_SUITE_P(SplitMoves, HighAccuracyRandomCasesJointTest,
                         ::testing::Values(88u, 146u));

// Joint interpolation: seeds that hold the targets only since stop 47's
// split for the joint bow (measured by the benchmark before: 89 at 1.69 x
// the clean DPO path's max |dev| with d2A 12 x the clean SPO path's, 116 at
// 1.24 x with d2C 9.3 x, 133 at d2A 5.2 x, 175 at d2A 1.72 x; 175 held at
// stop 40 and failed from stop 41's guards to stop 46).
INSTANTIATE_TEST_SUITE_P(SplitForTheJointBow, HighAccuracyRandomCasesJointTest,
                         ::testing::Values(89u, 116u, 133u, 175u));

// Joint interpolation: seeds that hold the targets only since stop 49's
// guards inside the moves either side of a cut's end pose for the points
// held there (AddTolerancePoints, solver/smooth/ceres_smoother.cc). Before,
// measured by the benchmark: 157 at d2A 6.5 x and d2C 4.0 x the clean SPO
// path's; 173 at d2A 44 x and d2C 81 x, every stiffer step refused for a
// floor corner point that its lead-in cut 0.0113 mm deep at any penalty.
INSTANTIATE_TEST_SUITE_P(EndOfCutMoveGuards, HighAccuracyRandomCasesJointTest,
                         ::testing::Values(157u, 173u));

// Joint interpolation: seeds that hold the targets only since stop 50's
// end-of-cut guards at a hundredth of the held point's weight
// (HighAccuracyOptions::end_of_cut_guard_weight). At its full weight,
// measured by the benchmark: 33 at 1.82 x the clean DPO path's max |dev|,
// 64 at d2A 2.40 x and d2C 4.12 x the clean SPO path's, 98 at d2C 2.87 x.
// Seeds 29 and 200 gained too, at a minute or two each.
INSTANTIATE_TEST_SUITE_P(EndOfCutGuardWeight, HighAccuracyRandomCasesJointTest,
                         ::testing::Values(33u, 64u, 98u));

// Seeds that hold the targets only since stop 41's guards (measured by the
// benchmark before: 52 at 1.62 x the clean DPO path's max |dev|, 3 um into
// the end ruling 0.7 of the way along a lead-in move that nothing guarded;
// 115 at 2.90 x and 125 at 1.25 x, R 2.0 and 2.2 mm, overcut at the
// rulings' ends where end guards at 0.15 mm alone lie outside a thin
// cutter's reach).
INSTANTIATE_TEST_SUITE_P(LeadMovesAndNearerEndGuards, HighAccuracyRandomCasesTest,
                         ::testing::Values(52u, 115u, 125u));

// Seeds that hold the targets only since the step with the peaks capped
// after the ten-fold steps (stop 52; measured by the benchmark before it:
// seed 1 d2A 2.10 x the clean SPO path's, 5.4 at stop 37, near the pole
// where the rulings give no reference and the clean DPO path's own is 7.1 x;
// 42 d2A 8.6 x; 190 d2A 2.17 x).
INSTANTIATE_TEST_SUITE_P(PeaksCappedAfterTheTenFoldSteps, HighAccuracyRandomCasesTest,
                         ::testing::Values(1u, 42u, 190u));

// Seeds whose clean DPO path is itself beyond 2 x the SPO path's peak d2A
// or d2C, held to max |dev| <= 1.0 x the DPO path's and each peak d2 within
// the larger of 2 x SPO and the DPO path's own (stop 37, README "Random
// cases"; measured by the benchmark: seed 1 d2A 5.4 x SPO, DPO 7.1 x; 55
// d2A 3.4 x, DPO 5.8 x; 64 d2C 2.1 x, DPO 3.8 x; 105 d2C 3.3 x, DPO 8.5 x;
// 183 d2A 2.8 x, DPO 3.2 x; 192 d2C 2.6 x, DPO 26 x). Seed 1 holds the strict
// target too since stop 52 (PeaksCappedAfterTheTenFoldSteps).
INSTANTIATE_TEST_SUITE_P(RoughReference, HighAccuracyRandomCasesRoughReferenceTest,
                         ::testing::Values(1u, 55u, 64u, 105u, 183u, 192u));

}  // namespace
}  // namespace tpopt
