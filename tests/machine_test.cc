#include "model/machine/machine.h"

#include <array>
#include <random>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct AxisVector {
  Eigen::Vector3d axis;
  double a0_deg, c0_deg, a1_deg, c1_deg;
};

// Published vectors of the foundation issue (pivot 0, no offsets).
TEST(AxisToAnglesTest, MatchesReferenceVectors) {
  const AxisVector cases[] = {
      {{0.5, 0, 0.866025}, 30, 90, -30, -90},
      {{0, 0.5, 0.866025}, 30, 0, -30, 180},
      {{0.3, -0.4, 0.866025}, 30, 143.1301, -30, -36.8699},
      {{-0.2, -0.1, 0.974679}, 12.9210, -116.5651, -12.9210, 63.4349},
  };
  for (const auto& c : cases) {
    const auto angles = AxisToAngles(c.axis.normalized());
    EXPECT_NEAR(angles[0].x() / kDeg, c.a0_deg, 2e-3) << c.axis.transpose();
    EXPECT_NEAR(angles[0].y() / kDeg, c.c0_deg, 2e-3) << c.axis.transpose();
    EXPECT_NEAR(angles[1].x() / kDeg, c.a1_deg, 2e-3) << c.axis.transpose();
    EXPECT_NEAR(angles[1].y() / kDeg, c.c1_deg, 2e-3) << c.axis.transpose();
  }
}

TEST(KinematicsTest, ReferenceWorkpiecePointToJoints) {
  Machine m;
  const JointVector j = m.ToJoints({10, 20, 5}, 30 * kDeg, 45 * kDeg);
  EXPECT_NEAR(j[kX], -7.071068, 1e-6);
  EXPECT_NEAR(j[kY], 15.871173, 1e-6);
  EXPECT_NEAR(j[kZ], 14.936729, 1e-6);
}

// The docs/ARCHITECTURE.md joint -> workpiece formulas, written out literally, as an
// independent reference for the factored implementation.
Eigen::Vector3d DesignFormula(const KinematicParams& k, const JointVector& j) {
  const double xr = k.rotary_pivot_mm.x(), yr = k.rotary_pivot_mm.y(),
               zr = k.rotary_pivot_mm.z();
  const double dy = k.y_offset_mm, dz = k.z_offset_mm + k.tool_length_mm;
  const double X = j[kX], Y = j[kY], Z = j[kZ];
  const double cA = std::cos(j[kA]), sA = std::sin(j[kA]);
  const double cC = std::cos(j[kC]), sC = std::sin(j[kC]);
  return {cC * (X - xr) + sC * cA * (Y - dy - yr) + sC * sA * (Z - dz - zr) + sC * dy + xr,
          -sC * (X - xr) + cC * cA * (Y - dy - yr) + cC * sA * (Z - dz - zr) + cC * dy + yr,
          -sA * (Y - dy - yr) + cA * (Z - dz - zr) + dz + zr};
}

TEST(KinematicsTest, RoundTripsRandomPosesIncludingNearSingular) {
  Machine m;
  m.kinematics.rotary_pivot_mm = {3, -7, 11};
  m.kinematics.y_offset_mm = 20;
  m.kinematics.z_offset_mm = 10;
  m.kinematics.tool_length_mm = 5;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-200, 200), ang(-M_PI, M_PI);
  for (int i = 0; i < 2000; ++i) {
    // Every fourth pose sits within 1e-7..1e-3 rad of A = 0.
    const double a = (i % 4 == 0) ? std::pow(10.0, -3 - 4 * (i % 7) / 6.0) : ang(rng);
    const double c = ang(rng);
    const Eigen::Vector3d p_w(pos(rng), pos(rng), pos(rng));
    const JointVector j = m.ToJoints(p_w, a, c);
    Eigen::Vector3d p_back, a_w;
    m.ToWorkpiece(j, &p_back, &a_w);
    ASSERT_LT((p_back - p_w).norm(), 1e-9) << "pose " << i;
    ASSERT_LT((DesignFormula(m.kinematics, j) - p_w).norm(), 1e-9) << "pose " << i;
    // Axis -> angles -> axis on both branches.
    // At the pole C is set to 0, which moves the axis by at most sin A.
    const double tol = std::abs(std::sin(a)) < Machine::kSingularSinA ? 2 * Machine::kSingularSinA : 1e-9;
    for (const auto& ac : AxisToAngles(a_w)) {
      ASSERT_LT((AnglesToAxis(ac.x(), ac.y()) - a_w).norm(), tol) << "pose " << i;
    }
  }
}

ToolPath PathFromAxes(const std::vector<Eigen::Vector3d>& axes) {
  ToolPath path;
  for (size_t i = 0; i < axes.size(); ++i) {
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(i, 0, 0);
    pose.a_w = axes[i].normalized();
    pose.source_line = static_cast<int>(i) + 1;
    path.poses.push_back(pose);
  }
  return path;
}

TEST(AssignJointsTest, UnwrapsCContinuouslyOverManyTurns) {
  std::vector<Eigen::Vector3d> axes;
  for (int i = 0; i <= 400; ++i) {
    const double c = i * 10 * kDeg;  // 11 turns
    axes.push_back(AnglesToAxis(20 * kDeg, c));
  }
  Machine m;
  std::vector<JointVector> j;
  ASSERT_TRUE(m.AssignJoints(PathFromAxes(axes), &j).ok());
  for (size_t i = 1; i < j.size(); ++i) {
    EXPECT_NEAR(std::abs(j[i][kC] - j[i - 1][kC]), 10 * kDeg, 1e-9);
  }
  EXPECT_NEAR(std::abs(j.back()[kC] - j.front()[kC]), 4000 * kDeg, 1e-6);
}

TEST(AssignJointsTest, PicksTheBranchInsideATravel) {
  // A in [-100, 50] deg (the LinuxCNC sim): an axis at 60 deg from +Z only
  // fits on the negative branch.
  Machine m;
  m.limits[kA].min = -100 * kDeg;
  m.limits[kA].max = 50 * kDeg;
  std::vector<Eigen::Vector3d> axes;
  for (int i = 0; i < 10; ++i) axes.push_back(AnglesToAxis(60 * kDeg, i * 3 * kDeg));
  std::vector<JointVector> j;
  ASSERT_TRUE(m.AssignJoints(PathFromAxes(axes), &j).ok());
  for (const auto& ji : j) EXPECT_NEAR(ji[kA], -60 * kDeg, 1e-9);
  // Both tips map back exactly.
  Eigen::Vector3d p, a;
  m.ToWorkpiece(j[3], &p, &a);
  EXPECT_LT((a - axes[3]).norm(), 1e-9);
}

TEST(AssignJointsTest, RejectsAOutsideTravelNamingThePose) {
  Machine m;
  m.limits[kA].min = -30 * kDeg;
  m.limits[kA].max = 30 * kDeg;
  std::vector<Eigen::Vector3d> axes(5, AnglesToAxis(10 * kDeg, 0.0));
  axes[3] = AnglesToAxis(45 * kDeg, 0.0);
  std::vector<JointVector> j;
  const Status s = m.AssignJoints(PathFromAxes(axes), &j);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 3"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("line 4"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("45"), std::string::npos) << s.message();
}

TEST(AssignJointsTest, HoldsCThroughTheSingularity) {
  // A pass straight over the pole: C must not jump at the singular pose.
  std::vector<Eigen::Vector3d> axes = {
      AnglesToAxis(2 * kDeg, 30 * kDeg), AnglesToAxis(1 * kDeg, 30 * kDeg),
      Eigen::Vector3d::UnitZ(), AnglesToAxis(-1 * kDeg, 30 * kDeg),
      AnglesToAxis(-2 * kDeg, 30 * kDeg)};
  Machine m;
  std::vector<JointVector> j;
  std::string warning;
  ASSERT_TRUE(m.AssignJoints(PathFromAxes(axes), &j, &warning).ok());
  EXPECT_NEAR(j[2][kC], j[1][kC], 1e-12);
  EXPECT_NE(warning.find("pose 2"), std::string::npos) << warning;
  // A straight pass over the pole is continuous motion through A = 0 with a
  // sign change of A; C stays put rather than flipping half a turn.
  EXPECT_NEAR(j[4][kC], j[0][kC], 1e-9);
  EXPECT_NEAR(j[0][kA], -j[4][kA], 1e-9);
  EXPECT_NEAR(std::abs(j[0][kA]), 2 * kDeg, 1e-9);
}

TEST(AssignJointsTest, LeadingSingularPosesTakeTheFirstDefinedC) {
  std::vector<Eigen::Vector3d> axes = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(),
                                       AnglesToAxis(5 * kDeg, 70 * kDeg)};
  Machine m;
  std::vector<JointVector> j;
  ASSERT_TRUE(m.AssignJoints(PathFromAxes(axes), &j).ok());
  EXPECT_NEAR(j[0][kC], j[2][kC], 1e-12);
}

TEST(AssignJointsTest, RejectsZeroLengthAxis) {
  ToolPath path = PathFromAxes({Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()});
  path.poses[1].a_w.setZero();
  Machine m;
  std::vector<JointVector> j;
  const Status s = m.AssignJoints(path, &j);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 1"), std::string::npos) << s.message();
}

// A path as a G-code program gives it: each pose's axis from its
// programmed (A, C) in degrees, which the pose keeps; `rapid` marks targets.
struct ProgrammedPose {
  bool rapid;
  double a_deg, c_deg;
};

ToolPath ProgrammedPath(const std::vector<ProgrammedPose>& program) {
  ToolPath path;
  for (size_t i = 0; i < program.size(); ++i) {
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(i, 0, 0);
    pose.rapid = program[i].rapid;
    pose.programmed = RotaryJoints{program[i].a_deg * kDeg, program[i].c_deg * kDeg};
    pose.a_w = AnglesToAxis(pose.programmed->a_rad, pose.programmed->c_rad);
    path.poses.push_back(pose);
  }
  return path;
}

// Assigns the joints of `path` on `m` and expects each pose's (A, C), deg.
void ExpectJointsDeg(const Machine& m, const ToolPath& path,
                     const std::vector<std::array<double, 2>>& ac_deg) {
  std::vector<JointVector> j;
  ASSERT_TRUE(m.AssignJoints(path, &j).ok());
  ASSERT_EQ(j.size(), ac_deg.size());
  for (size_t i = 0; i < j.size(); ++i) {
    EXPECT_NEAR(j[i][kA] / kDeg, ac_deg[i][0], 1e-9) << "pose " << i;
    EXPECT_NEAR(j[i][kC] / kDeg, ac_deg[i][1], 1e-9) << "pose " << i;
  }
}

TEST(AssignJointsTest, KeepsTheProgrammedWindingOfCAcrossRapids) {
  // A rapid to C 350, a cut winding C across 360 to 380, a rapid that
  // re-winds the table to C 20 (the same axis), a cut over A = 0 with C
  // programmed there, and the park at A 0 C 0. Unwrapped continuously, the
  // re-winding rapid would end at 380 and the park at 360 (or, holding C
  // at A = 0, at 20): real motion the program does not make.
  const std::vector<ProgrammedPose> program = {
      {true, -30, 350}, {false, -30, 360}, {false, -31, 370}, {false, -30, 380},
      {true, -30, 20},  {false, -10, 20},  {false, 0, 20},    {false, 10, 200},
      {true, 0, 0}};
  Machine m;
  m.limits[kC].min = -90 * kDeg;  // a path with programmed joints is not shifted
  m.limits[kC].max = 90 * kDeg;
  std::vector<std::array<double, 2>> as_programmed;
  for (const ProgrammedPose& p : program) as_programmed.push_back({p.a_deg, p.c_deg});
  ExpectJointsDeg(m, ProgrammedPath(program), as_programmed);
}

TEST(AssignJointsTest, APoseTurnedAwayFromItsProgramIsUnwrappedFromTheRapid) {
  // The cut's middle poses were turned by a smoother (their axis is no
  // longer the programmed one): they follow the rapid target's programmed C
  // 350, not the candidate in (-180, 180].
  ToolPath path = ProgrammedPath({{true, -30, 350}, {false, -30, 355}, {false, -30, 365},
                                  {false, -30, 370}, {true, 0, 0}});
  path.poses[1].a_w = AnglesToAxis(-30.5 * kDeg, 354 * kDeg);
  path.poses[2].a_w = AnglesToAxis(-30.5 * kDeg, 366 * kDeg);
  ExpectJointsDeg(Machine(), path, {{-30, 350}, {-30.5, 354}, {-30.5, 366}, {-30, 370}, {0, 0}});
}

TEST(AssignJointsTest, AStretchThatLeftTheProgramRejoinsItByTheNearestTurn) {
  // Turned poses 1-2 take C the other way round (-170 is reached as 190),
  // so the program's own poses after them are a whole turn off its winding:
  // they keep the program's steps from the nearest turn rather than spin
  // the table back within a cut; the rapid that follows is as programmed.
  ToolPath path = ProgrammedPath({{true, -30, 0}, {false, -30, 90}, {false, -30, 170},
                                  {false, -30, -160}, {false, -30, -150}, {true, -30, 10}});
  path.poses[1].a_w = AnglesToAxis(-30 * kDeg, 100 * kDeg);
  path.poses[2].a_w = AnglesToAxis(-30 * kDeg, -170 * kDeg);
  ExpectJointsDeg(Machine(), path,
                  {{-30, 0}, {-30, 100}, {-30, 190}, {-30, 200}, {-30, 210}, {-30, 10}});
}

TEST(AssignJointsTest, AProgramOnThePositiveBranchKeepsIt) {
  // Least motion alone could take either branch at A = +-20; the program
  // chose +20, and the free pose between follows it.
  ToolPath path = ProgrammedPath({{true, 20, 40}, {false, 20, 45}, {false, 20, 50}});
  path.poses[1].a_w = AnglesToAxis(21 * kDeg, 45 * kDeg);
  ExpectJointsDeg(Machine(), path, {{20, 40}, {21, 45}, {20, 50}});
}

TEST(AssignJointsTest, AProgramThatChangesBranchAtAToolChangeKeepsItsJoints) {
  // Tool 1 cuts on the negative branch (A -79.6), tool 2, after the tool
  // change's rapid, on the positive one (A +38.98) with C more than a quarter
  // turn away: a change of branch away from the pole, but the program's
  // own, so on a machine with unlimited A every pose keeps its joints (it
  // was refused as "outside the A travel [-inf, inf]"), and so it is with a
  // cut between whose axes a smoother turned.
  const std::vector<ProgrammedPose> program = {{true, -79.6, 10},  {false, -79.6, 12},
                                               {false, -79.0, 14}, {true, 38.98, -120},
                                               {false, 38.98, -118}, {false, 39.5, -116}};
  std::vector<std::array<double, 2>> as_programmed;
  for (const ProgrammedPose& p : program) as_programmed.push_back({p.a_deg, p.c_deg});
  ExpectJointsDeg(Machine(), ProgrammedPath(program), as_programmed);
  ToolPath turned = ProgrammedPath(program);
  turned.poses[2].a_w = AnglesToAxis(-79.2 * kDeg, 13 * kDeg);
  turned.poses[4].a_w = AnglesToAxis(39 * kDeg, -117 * kDeg);
  as_programmed[2] = {-79.2, 13};
  as_programmed[4] = {39, -117};
  ExpectJointsDeg(Machine(), turned, as_programmed);
  // The same change of branch inside a cut (a feed move, not a rapid, link
  // or held move) stays refused: a smoother would cut across its half turn.
  ToolPath in_cut = ProgrammedPath(program);
  in_cut.poses[3].rapid = false;
  std::vector<JointVector> j;
  const Status s = Machine().AssignJoints(in_cut, &j);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("change of branch away from the pole"), std::string::npos)
      << s.message();
}

TEST(AssignJointsTest, ABoundedTravelNamesItsLimitsAndTheReasonForEachBranch) {
  // The same program on A in [-100, 30]: tool 2's A +38.98 is beyond the
  // travel (and -38.98, inside it, is not the program's branch).
  Machine m;
  m.limits[kA].min = -100 * kDeg;
  m.limits[kA].max = 30 * kDeg;
  std::vector<JointVector> j;
  Status s = m.AssignJoints(
      ProgrammedPath({{true, -79.6, 10}, {false, -79.6, 12}, {true, 38.98, -120}}), &j);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 2 (line 0): A = 38.98 deg is outside the A travel [-100, 30] "
                             "deg, and A = -38.98 deg on the other branch is not the branch the "
                             "program gives"),
            std::string::npos)
      << s.message();
  // A program on the negative branch whose next pose a smoother turned to
  // 40 deg from +Z, C nearly the same, on A in [-30, 50]: only the positive
  // branch fits it, and tpopt does not change branch away from the pole.
  m.limits[kA].min = -30 * kDeg;
  m.limits[kA].max = 50 * kDeg;
  ToolPath path = ProgrammedPath({{true, -20, 10}, {false, -20, 12}});
  path.poses[1].a_w = AnglesToAxis(-40 * kDeg, 12 * kDeg);
  s = m.AssignJoints(path, &j);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("pose 1 (line 0): A = -40 deg is outside the A travel [-30, 50] deg"),
            std::string::npos)
      << s.message();
  EXPECT_NE(s.message().find("change of branch away from the pole"), std::string::npos)
      << s.message();
}

TEST(CheckTravelTest, NamesThePoseTheAxisTheValueAndTheTravel) {
  Machine m;
  m.limits[kX].min = -10.0;
  m.limits[kX].max = 10.0;
  m.limits[kC].min = -90 * kDeg;
  m.limits[kC].max = 90 * kDeg;
  std::vector<Eigen::Vector3d> axes(5, AnglesToAxis(10 * kDeg, 0.0));
  const ToolPath path = PathFromAxes(axes);
  std::vector<JointVector> j(5, JointVector::Zero());
  EXPECT_TRUE(m.CheckTravel(path, j).ok());
  j[2][kX] = 12.5;
  Status s = m.CheckTravel(path, j);
  ASSERT_FALSE(s.ok());
  for (const char* part : {"pose 2", "line 3", "X = 12.5", "[-10, 10]"}) {
    EXPECT_NE(s.message().find(part), std::string::npos) << part << ": " << s.message();
  }
  j[2][kX] = 0.0;
  j[4][kC] = 120 * kDeg;  // reported in degrees, as the machine file gives it
  s = m.CheckTravel(path, j);
  ASSERT_FALSE(s.ok());
  for (const char* part : {"pose 4", "C = 120", "[-90, 90]"}) {
    EXPECT_NE(s.message().find(part), std::string::npos) << part << ": " << s.message();
  }
}

}  // namespace
}  // namespace tpopt
