// The smoother's safety invariants through the whole pipeline: a path
// outside the machine's travel is refused as bad input, the smoother never
// writes a path that leaves the travel, whatever it would have liked to do,
// and it never leaves the surface farther than the stated tolerance where
// the input was closer.
#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/path/rail_projection.h"
#include "solver/smooth/even_stations.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

class SafetyInvariantsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(testing::LoadImpellerBench(&surface_, &machine_));
    FlankPathOptions g;
    g.poses = 150;
    g.uv_distortion = 0.03;
    g.axis_noise_deg = 0.3;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &input_).ok());
    cutter_ = *input_.cutter;
  }

  Status Smooth(const Machine& machine, SmoothingMode mode, SmoothingResult* result) {
    SmoothingSettings settings;
    settings.mode = mode;
    return RunSmoothing({&input_, &surface_, &cutter_, &machine}, settings, result);
  }

  // The least and greatest value of each joint over `path`.
  std::pair<JointVector, JointVector> JointRange(const ToolPath& path) {
    std::vector<JointVector> joints;
    EXPECT_TRUE(machine_.AssignJoints(path, &joints).ok());
    JointVector lo = joints[0], hi = joints[0];
    for (const JointVector& j : joints) {
      lo = lo.cwiseMin(j);
      hi = hi.cwiseMax(j);
    }
    return {lo, hi};
  }

  // The machine with its X, Y, Z and C travel cut to what the input uses.
  Machine TravelOfInput() {
    const auto [lo, hi] = JointRange(input_);
    Machine tight = machine_;
    for (int a : {kX, kY, kZ, kC}) {
      tight.limits[a].min = lo[a] - 1e-6;
      tight.limits[a].max = hi[a] + 1e-6;
    }
    return tight;
  }

  RuledSurface surface_;
  Machine machine_;
  ToolPath input_;
  Cutter cutter_;
};

TEST_F(SafetyInvariantsTest, InputOutsideTheTravelIsBadInputNamingPoseAndAxis) {
  const auto [lo, hi] = JointRange(input_);
  Machine narrow = machine_;
  narrow.limits[kX].max = 0.5 * (lo[kX] + hi[kX]);  // half the input's X range
  SmoothingResult result;
  const Status s = Smooth(narrow, SmoothingMode::kHighAccuracy, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.code(), StatusCode::kBadInput);
  EXPECT_NE(s.message().find("pose "), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("X = "), std::string::npos) << s.message();
}

// The travel is set to exactly what the input uses on X, Y, Z and C. The
// high-accuracy smoother wants to go beyond it (checked on the machine
// without those limits; the spline method happens to stay inside here), so
// in each mode it must either stay inside or refuse.
TEST_F(SafetyInvariantsTest, OutputNeverLeavesTheTravel) {
  const Machine tight = TravelOfInput();
  for (SmoothingMode mode : {SmoothingMode::kSpline, SmoothingMode::kHighAccuracy}) {
    SCOPED_TRACE(mode == SmoothingMode::kSpline ? "spline" : "high_accuracy");
    SmoothingResult loose;
    ASSERT_TRUE(Smooth(machine_, mode, &loose).ok());
    const auto [out_lo, out_hi] = JointRange(loose.output);
    bool leaves = false;
    for (int a : {kX, kY, kZ, kC}) {
      leaves = leaves || out_lo[a] < tight.limits[a].min || out_hi[a] > tight.limits[a].max;
    }
    if (mode == SmoothingMode::kHighAccuracy) {
      ASSERT_TRUE(leaves) << "the scenario must tempt the smoother out of the travel";
    }

    SmoothingResult result;
    const Status s = Smooth(tight, mode, &result);
    if (s.ok()) {
      std::vector<JointVector> joints;
      ASSERT_TRUE(tight.AssignJoints(result.output, &joints).ok());
      EXPECT_TRUE(tight.CheckTravel(result.output, joints).ok());
    } else {
      EXPECT_EQ(s.code(), StatusCode::kSolver) << s.message();
      EXPECT_NE(s.message().find("travel"), std::string::npos) << s.message();
    }
  }
}

// Without the travel walls, every high-accuracy solve on the travel the
// input uses leaves it (refused at even stations and at the program's own).
// The input fits, so the program goes back as programmed, every run kept
// with the solver's failure as its reason, instead of a refusal (issue 16);
// with the never-worse rule off, the refusal stands, naming the travel.
TEST_F(SafetyInvariantsTest, AProgramEverySolveOfWhichFailsGoesBackAsProgrammed) {
  const Machine tight = TravelOfInput();
  SmoothingSettings settings;
  settings.mode = SmoothingMode::kHighAccuracy;
  settings.high_accuracy.w_walls = 0;
  SmoothingResult result;
  ASSERT_TRUE(RunSmoothing({&input_, &surface_, &cutter_, &tight}, settings, &result).ok());
  ASSERT_EQ(result.runs_kept.size(), 1u);
  EXPECT_EQ(result.runs_kept_as_input, 1);
  EXPECT_EQ(result.runs_kept[0].reason, "solver");
  EXPECT_NE(result.runs_kept[0].solver_message.find("travel"), std::string::npos)
      << result.runs_kept[0].solver_message;
  ASSERT_EQ(result.output.poses.size(), input_.poses.size());
  for (size_t i = 0; i < input_.poses.size(); ++i) {
    EXPECT_EQ(result.output.poses[i].p_w_tip, input_.poses[i].p_w_tip) << "pose " << i;
    EXPECT_EQ(result.output.poses[i].a_w, input_.poses[i].a_w) << "pose " << i;
  }
  settings.keep_runs_no_worse = false;
  const Status refused = RunSmoothing({&input_, &surface_, &cutter_, &tight}, settings, &result);
  EXPECT_EQ(refused.code(), StatusCode::kSolver);
  EXPECT_NE(refused.message().find("travel"), std::string::npos) << refused.message();
}

// CAM writes flank paths with the tip below the floor (issue 16): the SPO
// path with its tip moved 2 mm down its axis, with a U/V bump and axis noise,
// on LinuxCNC's sim machine. The smoother once pulled every tip up to rail 0
// and left the travel (impeller, Y = -157) or the tolerance (jcde2022). Now
// each output tip keeps its overhang, every axis stays within its cone, the
// result fits the machine and beats the clean DPO path on deviation.
TEST(OverhangTest, TipBelowTheFloorKeepsItsOverhangAndFitsTheMachine) {
  Machine sim;
  ASSERT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &sim)
          .ok());
  for (const char* name : {"impeller_blade", "jcde2022"}) {
    SCOPED_TRACE(name);
    RuledSurface surface;
    ASSERT_TRUE(ReadSurfaceJson(
                    testing::SourcePath(std::string("data/surfaces/") + name + ".json"), &surface)
                    .ok());
    FlankPathOptions g;
    ToolPath dpo, cam;
    g.strategy = FlankStrategy::kDoublePointOffset;
    ASSERT_TRUE(GenerateFlankPath(surface, g, &dpo).ok());
    g.strategy = FlankStrategy::kSinglePointOffset;
    g.uv_distortion = 0.03;
    g.axis_noise_deg = 0.3;
    ASSERT_TRUE(GenerateFlankPath(surface, g, &cam).ok());
    constexpr double kOverhangMm = 2.0;
    for (ToolPose& p : cam.poses) p.p_w_tip -= kOverhangMm * p.a_w;
    // At the program's own stations each pose's contact is the generator's
    // u = i / (n - 1); at even stations (the default), the contact of the
    // station the solve ties it to (solver/smooth/even_stations.h, tested
    // against closed forms in even_stations_test).
    for (const bool even : {false, true}) {
      SCOPED_TRACE(even ? "even stations" : "the program's stations");
      SmoothingSettings settings;
      settings.even_stations = even;
      // Pose for pose against the program (under joint interpolation its
      // moves would be split for their bow: split_moves_for_tolerance).
      settings.split_moves_for_tolerance = 1;
      SmoothingResult result;
      const Status s = RunSmoothing({&cam, &surface, &*cam.cutter, &sim}, settings, &result);
      ASSERT_TRUE(s.ok()) << s.message();
      const size_t n = cam.poses.size();
      ASSERT_EQ(result.output.poses.size(), n);
      std::vector<double> u(n);
      for (size_t i = 0; i < n; ++i) u[i] = i / (n - 1.0);
      if (even) {
        ToolPath stations;
        ASSERT_TRUE(
            EvenStations(cam, surface, sim, settings.deviation.interpolation, 1, &stations).ok());
        u = ProjectPathOntoRail(surface.rail(0), stations);
      }
      for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d floor_w = surface.rail(0).Point(u[i]);
        const ToolPose& out = result.output.poses[i];
        EXPECT_NEAR((floor_w - out.p_w_tip).dot(out.a_w), kOverhangMm, 0.1) << i;
        const double turn_deg =
            std::acos(std::min(1.0, out.a_w.dot(cam.poses[i].a_w))) * 180 / M_PI;
        EXPECT_LE(turn_deg, HighAccuracyOptions().axis_cone_deg) << i;
      }
      PathMetrics dpo_metrics;
      ASSERT_TRUE(EvaluatePath(dpo, sim, &surface, *dpo.cutter, settings.deviation,
                               settings.motion, &dpo_metrics)
                      .ok());
      EXPECT_LE(WorstDeviationMm(result.output_metrics), WorstDeviationMm(dpo_metrics));
    }
  }
}

}  // namespace
}  // namespace tpopt

namespace tpopt {
namespace {

// The stated tolerance: no point of the surface ends up farther from the
// cutter than --tolerance_mm unless the input was farther still there. The
// hypar's distorted CAM path misses it by a fraction of a micrometre at the
// tolerance unit, and meets it once that unit is halved. The clean SPO path
// lies within kTightMm where it crosses the pole, and no smooth path found
// there does, so its run goes back as programmed unless the caller accepts
// the solve (it was refused until stop 23). (At 0.01 mm
// it used to be refused too; since the active set's dead band and the start
// placed on the surface it is held within 0.01 mm.)
constexpr double kTightMm = 0.005;
class ToleranceInvariantTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/hypar.json"), &surface_).ok());
    ASSERT_TRUE(
        ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &machine_).ok());
    FlankPathOptions g;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &clean_spo_).ok());
    g.uv_distortion = 0.03;
    g.axis_noise_deg = 0.3;
    ASSERT_TRUE(GenerateFlankPath(surface_, g, &cam_).ok());
  }

  Status Smooth(const ToolPath& input, double tolerance_mm, bool accept_over_tolerance,
                SmoothingResult* result,
                double stiffer_above_flank_d2 = SmoothingSettings().stiffer_above_flank_d2) {
    SmoothingSettings settings;
    settings.high_accuracy.tolerance_mm = tolerance_mm;
    settings.accept_over_tolerance = accept_over_tolerance;
    settings.stiffer_above_flank_d2 = stiffer_above_flank_d2;
    // What goes back as programmed, at the program's own move count (the
    // split moves that may keep a run instead are tested on random cases).
    settings.split_moves_for_tolerance = 1;
    return RunSmoothing({&input, &surface_, &*input.cutter, &machine_}, settings, result);
  }

  // Largest |deviation| of `out` at grid points where it exceeds the
  // input's own |deviation| by more than `slack_mm`.
  static double WorstBeyondInput(const SmoothingResult& r, double slack_mm = 0.0) {
    const DeviationReport& in = *r.input_metrics.deviation;
    const DeviationReport& out = *r.output_metrics.deviation;
    double worst = 0.0;
    for (size_t k = 0; k < out.deviation_mm.size(); ++k) {
      const double d = std::abs(out.deviation_mm[k]);
      if (d > std::abs(in.deviation_mm[k]) + slack_mm) worst = std::max(worst, d);
    }
    return worst;
  }

  RuledSurface surface_;
  Machine machine_;
  ToolPath clean_spo_, cam_;
};

// The tolerance is a constraint on the points that break it, not a weight
// on the whole surface: the solve's unit stays the stated tolerance, and
// only a few grid points (those a solve left beyond it and their grid
// neighbours) get a penalty of their own. Without the stiffer solves that
// rough axes ask for (SmoothingSettings::stiffer_above_flank_d2): those
// start from the first solve's result, which here they bring within the
// tolerance, and hold points of their own.
TEST_F(ToleranceInvariantTest, HoldsThePointsBeyondTheToleranceUntilItHolds) {
  SmoothingResult first, held;
  ASSERT_TRUE(Smooth(cam_, 0.01, /*accept_over_tolerance=*/true, &first, 0.0).ok());
  EXPECT_GT(WorstBeyondInput(first), 0.01);  // the first solve misses it
  EXPECT_EQ(first.tolerance_rounds, 0);
  const Status s = Smooth(cam_, 0.01, /*accept_over_tolerance=*/false, &held, 0.0);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(held.solve_tolerance_mm, 0.01);
  EXPECT_GE(held.tolerance_rounds, 1);
  const size_t grid = held.output_metrics.deviation->deviation_mm.size();
  EXPECT_GT(held.tolerance_points, 0);
  EXPECT_LT(held.tolerance_points, 0.02 * grid) << grid;
  EXPECT_LE(WorstBeyondInput(held), 0.01);
}

// What the tolerance rounds cannot hold is not refused (issue 17: no
// refusal for what the input did not do): the run that reaches the points
// left beyond goes back as programmed, so no point is beyond both the
// tolerance and the input. Refused with exit 3 until stop 23. The clean SPO
// path at 100 poses: the first solve and its three retries (issue 16, stop
// 25) all leave points beyond kTightMm. (At 300 poses a retry holds it, and
// the d2 rule then puts the run back after its stiffer solves: 6 min at
// stop 25, with two.)
TEST_F(ToleranceInvariantTest, PutsBackWhatCannotBeHeldUnlessAccepted) {
  FlankPathOptions g;
  g.poses = 100;
  ASSERT_TRUE(GenerateFlankPath(surface_, g, &clean_spo_).ok());
  SmoothingResult result;
  const Status s =
      Smooth(clean_spo_, kTightMm, /*accept_over_tolerance=*/false, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(result.tolerance_rounds, 4);
  EXPECT_EQ(result.runs_kept_as_input, 1);
  ASSERT_EQ(result.runs_kept.size(), 1u);
  EXPECT_EQ(result.runs_kept[0].reason, "tolerance");
  EXPECT_EQ(WorstBeyondInput(result), 0.0);
  ASSERT_EQ(result.output.poses.size(), clean_spo_.poses.size());
  for (size_t i = 0; i < clean_spo_.poses.size(); ++i) {
    EXPECT_EQ(result.output.poses[i].p_w_tip, clean_spo_.poses[i].p_w_tip) << i;
    EXPECT_EQ(result.output.poses[i].a_w, clean_spo_.poses[i].a_w) << i;
  }
  // Accepted, the solve stands against the tolerance (the noisy CAM path's
  // first solve above is returned beyond it), but not against the input's
  // smoothness: on this path, smooth already, the solve raised the peak
  // d2A/ds2 or d2C/ds2, so its one run goes back as programmed and the
  // program comes back with the input's own deviation.
  const Status accepted =
      Smooth(clean_spo_, kTightMm, /*accept_over_tolerance=*/true, &result);
  ASSERT_TRUE(accepted.ok()) << accepted.message();
  EXPECT_EQ(result.runs_kept_as_input, 1);
  EXPECT_EQ(WorstBeyondInput(result), 0.0);
  for (int axis : {kA, kC}) {
    EXPECT_EQ(result.output_metrics.motion.axes[axis].peak_second_derivative_per_mm2,
              result.input_metrics.motion.axes[axis].peak_second_derivative_per_mm2)
        << axis;
  }
}

// High accuracy puts back the runs it makes worse on peak d2A/ds2 or
// d2C/ds2 than the input's (SmoothingSettings::keep_runs_no_worse), and
// puts runs back after its tolerance check without
// breaking the tolerance. The program: the noisy CAM
// path to u = 0.75, a link, then the clean SPO path on (already smooth,
// so the solve can only roughen it). The second run goes back as programmed, pose for pose;
// the first stays smoothed.
TEST_F(ToleranceInvariantTest, PutsBackTheRunsItWouldMakeWorseWithinTheTolerance) {
  ASSERT_EQ(cam_.poses.size(), clean_spo_.poses.size());
  ToolPath input = cam_;
  const size_t first_clean = input.poses.size() * 3 / 4;
  std::copy(clean_spo_.poses.begin() + first_clean, clean_spo_.poses.end(),
            input.poses.begin() + first_clean);
  input.poses[first_clean].link = true;
  SmoothingResult result;
  const Status s = Smooth(input, 0.01, /*accept_over_tolerance=*/false, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(result.runs_kept_as_input, 1);
  ASSERT_EQ(result.output.poses.size(), input.poses.size());
  double moved_mm = 0.0;
  for (size_t i = 0; i < input.poses.size(); ++i) {
    const double d = (result.output.poses[i].p_w_tip - input.poses[i].p_w_tip).norm() +
                     (result.output.poses[i].a_w - input.poses[i].a_w).norm();
    if (i >= first_clean) {
      EXPECT_EQ(d, 0.0) << "pose " << i;
    } else {
      moved_mm = std::max(moved_mm, d);
    }
  }
  EXPECT_GT(moved_mm, 1e-3);  // the CAM run was smoothed
  for (int axis : {kA, kC}) {
    EXPECT_LE(result.output_metrics.motion.axes[axis].peak_second_derivative_per_mm2,
              result.input_metrics.motion.axes[axis].peak_second_derivative_per_mm2)
        << axis;
  }
  // Where the put-back run cuts, the input's moves give the input's
  // deviation, evaluated again to round-off (1 nm is far above it).
  EXPECT_LE(WorstBeyondInput(result, 1e-6), 0.01);
}

}  // namespace
}  // namespace tpopt
