#include "solver/smooth/lead_continuation.h"

#include <cmath>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/machine/axis_metrics.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

Machine SimMachine() {
  Machine m;
  EXPECT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &m).ok());
  return m;
}

// A straight path along X, 1 mm steps, whose axis turns linearly in the
// tip's arc length over the cut (A from 30 deg at 0.5 deg/mm, C from 10 deg
// at -0.3 deg/mm), with `lead_in` poses before it and `lead_out` after it
// that hold the end axes, as CAM writes them.
struct LeadPath {
  ToolPath path;
  std::vector<bool> lead;
};

LeadPath MakePath(int lead_in, int cut, int lead_out) {
  LeadPath p;
  const int n = lead_in + cut + lead_out;
  for (int i = 0; i < n; ++i) {
    const int k = std::clamp(i - lead_in, 0, cut - 1);  // the cut pose whose axis it holds
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(i, 0, 0);
    pose.a_w = AnglesToAxis((30 + 0.5 * k) * kDeg, (10 - 0.3 * k) * kDeg);
    pose.feed_mm_per_min = 1000;
    p.path.poses.push_back(pose);
    p.lead.push_back(i < lead_in || i >= lead_in + cut);
  }
  return p;
}

LeadContinuation How(double rate_fraction, double cone_deg) {
  LeadContinuation how;
  how.rate_fraction = rate_fraction;
  how.cone_deg = cone_deg;
  return how;
}

std::array<double, 2> PeakSecond(const Machine& machine, const ToolPath& path) {
  std::vector<JointVector> joints;
  EXPECT_TRUE(machine.AssignJoints(path, &joints).ok());
  const MotionSamples m = ComputeMotionSamples(machine, path, joints, 1000);
  std::array<double, 2> peak = {0, 0};
  for (size_t i = 0; i < path.poses.size(); ++i) {
    peak[0] = std::max(peak[0], SecondDerivativePerMm2(path, joints, m, i, kA));
    peak[1] = std::max(peak[1], SecondDerivativePerMm2(path, joints, m, i, kC));
  }
  return peak;
}

TEST(LeadContinuationTest, LeadsContinueTheCutsRatesSoNoJunctionBendsTheAxes) {
  const Machine machine = SimMachine();
  LeadPath p = MakePath(3, 10, 2);
  const ToolPath programmed = p.path;
  // As programmed, the rotary axes stop dead at both junctions:
  // 0.5 deg/mm of A lost over a 1 mm step.
  EXPECT_NEAR(PeakSecond(machine, programmed)[0], 0.5 * kDeg, 1e-9);
  EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 12.0), &p.path), 5);
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(p.path, &joints).ok());
  for (size_t i = 0; i < joints.size(); ++i) {
    // The closed form: A and C linear in the tip's arc length throughout.
    const double s = static_cast<double>(i) - 3;
    EXPECT_NEAR(joints[i][kA], (30 + 0.5 * s) * kDeg, 1e-9) << "pose " << i;
    EXPECT_NEAR(joints[i][kC], (10 - 0.3 * s) * kDeg, 1e-9) << "pose " << i;
    EXPECT_EQ(p.path.poses[i].p_w_tip, programmed.poses[i].p_w_tip);
  }
  const std::array<double, 2> peak = PeakSecond(machine, p.path);
  EXPECT_LT(peak[0], 1e-9);
  EXPECT_LT(peak[1], 1e-9);
}

TEST(LeadContinuationTest, AFractionOfTheRatesOrTheJunctionsAxisHeld) {
  const Machine machine = SimMachine();
  for (double fraction : {0.5, 0.0}) {
    LeadPath p = MakePath(3, 10, 0);
    const ToolPath programmed = p.path;
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(fraction, 12.0), &p.path), 3);
    for (int i = 0; i < 3; ++i) {
      const double s = i - 3.0;
      const Eigen::Vector3d expected =
          AnglesToAxis((30 + fraction * 0.5 * s) * kDeg, (10 - fraction * 0.3 * s) * kDeg);
      EXPECT_NEAR((p.path.poses[i].a_w - expected).norm(), 0.0, 1e-12) << "pose " << i;
    }
  }
}

TEST(LeadContinuationTest, TheTipsAlongTheCutWithinTheirBand) {
  const Machine machine = SimMachine();
  // The programmed lead-in comes in 0.3 mm to the side of the cut's line.
  LeadPath p = MakePath(3, 10, 0);
  for (int i = 0; i < 3; ++i) p.path.poses[i].p_w_tip.y() = 0.3;
  const ToolPath programmed = p.path;
  LeadContinuation how = How(1.0, 12.0);
  how.along_cut = true;
  how.band_mm = 0.2;
  EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, how, &p.path), 0);
  how.band_mm = 1.0;
  EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, how, &p.path), 3);
  double away = 0;
  for (int i = 2; i >= 0; --i) {
    // On the cut's line (y = 0), at the lead's own steps from the junction.
    away += (programmed.poses[i].p_w_tip - programmed.poses[i + 1].p_w_tip).norm();
    EXPECT_NEAR((p.path.poses[i].p_w_tip - Eigen::Vector3d(3 - away, 0, 0)).norm(), 0.0, 1e-9)
        << "pose " << i;
  }
  EXPECT_LT(PeakSecond(machine, p.path)[0], 1e-9);
}

TEST(LeadContinuationTest, ALeadIsLeftWhereItsContinuationBreaksARule) {
  const Machine machine = SimMachine();
  {
    // A held pose keeps its programmed axis, and so does its stretch.
    LeadPath p = MakePath(2, 6, 0);
    p.path.poses[0].held = true;
    const ToolPath programmed = p.path;
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 12.0), &p.path), 0);
    EXPECT_EQ(p.path.poses[1].a_w, programmed.poses[1].a_w);
  }
  {
    // 30 poses of lead-in at 0.5 deg/mm leave a 2 deg cone.
    LeadPath p = MakePath(30, 6, 0);
    const ToolPath programmed = p.path;
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 2.0), &p.path), 0);
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 20.0), &p.path), 30);
  }
  {
    // A rapid into the cut: nothing to continue.
    LeadPath p = MakePath(2, 6, 0);
    p.path.poses[2].rapid = true;
    const ToolPath programmed = p.path;
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 12.0), &p.path), 0);
  }
  {
    // A cut whose first move is a micrometre takes its rate from the next.
    LeadPath p = MakePath(2, 6, 0);
    for (size_t i = 3; i < p.path.poses.size(); ++i) p.path.poses[i].p_w_tip.x() -= 1 - 1e-4;
    p.path.poses[3].a_w = p.path.poses[2].a_w;
    const ToolPath programmed = p.path;
    EXPECT_EQ(ContinueLeads(machine, p.lead, programmed, How(1.0, 12.0), &p.path), 2);
    std::vector<JointVector> joints;
    ASSERT_TRUE(machine.AssignJoints(p.path, &joints).ok());
    const double rate = (joints[4][kA] - joints[2][kA]) /
                        (p.path.poses[4].p_w_tip - p.path.poses[2].p_w_tip).norm();
    EXPECT_NEAR((joints[2][kA] - joints[1][kA]) / 1.0, rate, 1e-9);
  }
}

}  // namespace
}  // namespace tpopt
