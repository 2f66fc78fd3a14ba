#include "model/eval/random_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "model/io/json_io.h"
#include "model/path/rail_projection.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

double AngleRad(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(RandomCasesTest, SameSeedSameCaseOtherSeedOtherCase) {
  const std::vector<Machine> machines = testing::SharedMachines();
  RandomCase a, b, c;
  ASSERT_TRUE(MakeRandomCase(7, RandomCaseOptions(), machines, &a).ok());
  ASSERT_TRUE(MakeRandomCase(7, RandomCaseOptions(), machines, &b).ok());
  ASSERT_TRUE(MakeRandomCase(8, RandomCaseOptions(), machines, &c).ok());
  EXPECT_EQ(a.description, b.description);
  ASSERT_EQ(a.cam_path.poses.size(), b.cam_path.poses.size());
  for (size_t i = 0; i < a.cam_path.poses.size(); ++i) {
    EXPECT_EQ(a.cam_path.poses[i].p_w_tip, b.cam_path.poses[i].p_w_tip);
    EXPECT_EQ(a.cam_path.poses[i].a_w, b.cam_path.poses[i].a_w);
  }
  EXPECT_NE(a.description, c.description);
}

TEST(RandomCasesTest, BadOptionsAreRefused) {
  RandomCaseOptions o;
  o.poses = 3;
  RandomCase c;
  const Status s = MakeRandomCase(1, o, testing::SharedMachines(), &c);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("poses must be >= 4 (got 3)"), std::string::npos) << s.message();
}

// The drawn parameters stay in the ranges and, over 60 seeds, cover
// every rail degree, both sides, both machines, pole and non-pole cases.
TEST(RandomCasesTest, ParametersSpanTheRanges) {
  const std::vector<Machine> machines = testing::SharedMachines();
  std::set<int> degrees;
  std::set<std::string> machine_names;
  std::set<CutterSide> sides;
  int near_pole = 0, taper = 0, bump = 0, micro = 0, lead = 0, fits = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    RandomCase c;
    ASSERT_TRUE(MakeRandomCase(seed, RandomCaseOptions(), machines, &c).ok());
    const RandomCaseParameters& p = c.parameters;
    SCOPED_TRACE(c.description);
    EXPECT_GE(p.rail_degree, 1);
    EXPECT_LE(p.rail_degree, 3);
    EXPECT_EQ(c.surface.rail(0).degree(), p.rail_degree);
    EXPECT_GE(std::abs(p.twist_deg), 5.0);
    EXPECT_LE(std::abs(p.twist_deg), 50.0);
    EXPECT_GE(p.size_mm, 20.0);
    EXPECT_LE(p.size_mm, 150.0);
    EXPECT_GE(p.cutter_radius_mm, 2.0);
    EXPECT_LE(p.cutter_radius_mm, 8.0);
    EXPECT_GE(p.taper_deg, 0.0);
    EXPECT_LE(p.taper_deg, 5.0);
    EXPECT_GE(p.overhang_mm, 0.0);
    EXPECT_LE(p.overhang_mm, 3.0);
    EXPECT_LE(p.axis_noise_deg, 0.5);
    EXPECT_LE(std::abs(p.uv_bump), 0.03);
    EXPECT_NEAR(c.cutter.taper_rad, p.taper_deg * kDeg, 1e-12);
    degrees.insert(p.rail_degree);
    machine_names.insert(c.machine.name);
    sides.insert(p.side);
    near_pole += p.near_pole;
    taper += p.taper_deg > 0;
    bump += p.uv_bump != 0;
    micro += p.micro_steps > 0;
    lead += p.lead_in_poses + p.lead_out_poses > 0;
    fits += c.fits_machine;
    EXPECT_EQ(c.fits_machine, c.fit_note.empty());
  }
  EXPECT_EQ(degrees.size(), 3u);
  EXPECT_EQ(machine_names.size(), 2u);
  EXPECT_EQ(sides.size(), 2u);
  for (int count : {near_pole, taper, bump, micro, lead}) {
    EXPECT_GT(count, 5);
    EXPECT_LT(count, 60);
  }
  // Most parts fit; the ones that do not say so (above).
  EXPECT_GT(fits, 40);
}

// Each body pose of the CAM path touches its contact point C1(u) with the
// flank at the overhang's height, and its axis lies within taper + the noise
// bound + the bump's swing of the true ruling; lead poses lie beyond the
// surface's ends; 1 um steps exist where drawn.
TEST(RandomCasesTest, CamPathFollowsItsConvention) {
  const std::vector<Machine> machines = testing::SharedMachines();
  for (unsigned seed = 1; seed <= 30; ++seed) {
    RandomCase c;
    ASSERT_TRUE(MakeRandomCase(seed, RandomCaseOptions(), machines, &c).ok());
    SCOPED_TRACE(c.description);
    const RandomCaseParameters& p = c.parameters;
    const std::vector<ToolPose>& poses = c.cam_path.poses;
    ASSERT_EQ(c.cam_u.size(), poses.size());
    ASSERT_EQ(static_cast<int>(poses.size()),
              60 + p.micro_steps + p.lead_in_poses + p.lead_out_poses);
    double least_step_mm = 1e9;
    for (size_t i = 0; i < poses.size(); ++i) {
      if (i > 0)
        least_step_mm = std::min(
            least_step_mm, (poses[i].p_w_tip - poses[i - 1].p_w_tip).norm());
      const double u = c.cam_u[i];
      if (std::isnan(u)) continue;
      const Eigen::Vector3d c1 = c.surface.rail(0).Point(u);
      const ToolPose& pose = poses[i];
      EXPECT_NEAR((c1 - pose.p_w_tip).dot(pose.a_w), p.overhang_mm, 1e-9);
      EXPECT_NEAR(
          SignedDistanceToFlank<double>(c.cutter, c1, pose.p_w_tip, pose.a_w),
          0.0, 1e-9);
      // The cutter is on the surface's cutter side.
      EXPECT_GT((pose.p_w_tip - c1).dot(c.surface.Normal(u, 0)), 0.0);
      const Eigen::Vector3d ruling = c.surface.rail(1).Point(u) - c1;
      const double bump_swing_rad =
          std::atan(std::abs(p.uv_bump) * 2.0 * p.size_mm / ruling.norm());
      EXPECT_LE(
          AngleRad(pose.a_w, ruling),
          (p.taper_deg + 5 * p.axis_noise_deg) * kDeg + bump_swing_rad + 1e-9);
    }
    if (p.micro_steps > 0) {
      EXPECT_LT(least_step_mm, 1.5e-3);
      EXPECT_GT(least_step_mm, 0.5e-3);
    }
    // Lead poses: their foot on rail 0 is clamped to the end, and they lie
    // beyond it along the rail's tangent.
    for (int k = 0; k < p.lead_in_poses; ++k) {
      const auto c1 = c.surface.rail(0).Evaluate(0.0, 1);
      EXPECT_LT((poses[static_cast<size_t>(k)].p_w_tip - c1[0]).dot(c1[1]),
                0.0);
      EXPECT_EQ(ProjectOntoCurve(c.surface.rail(0),
                                 poses[static_cast<size_t>(k)].p_w_tip),
                0.0);
    }
    for (int k = 0; k < p.lead_out_poses; ++k) {
      const auto c1 = c.surface.rail(0).Evaluate(1.0, 1);
      const ToolPose& pose = poses[poses.size() - 1 - static_cast<size_t>(k)];
      EXPECT_GT((pose.p_w_tip - c1[0]).dot(c1[1]), 0.0);
    }
  }
}

// A near-pole case has some ruling within its pole offset of +Z (to the
// half degree the bow of the rail adds).
TEST(RandomCasesTest, NearPoleCasesPassNearThePole) {
  const std::vector<Machine> machines = testing::SharedMachines();
  int checked = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    RandomCase c;
    ASSERT_TRUE(MakeRandomCase(seed, RandomCaseOptions(), machines, &c).ok());
    SCOPED_TRACE(c.description);
    double least_rad = M_PI;
    for (int i = 0; i <= 2000; ++i) {
      const double u = i / 2000.0;
      const Eigen::Vector3d ruling =
          c.surface.rail(1).Point(u) - c.surface.rail(0).Point(u);
      least_rad =
          std::min(least_rad, AngleRad(ruling, Eigen::Vector3d::UnitZ()));
    }
    if (c.parameters.near_pole) {
      EXPECT_NEAR(least_rad / kDeg, c.parameters.pole_offset_deg, 0.5);
      ++checked;
    }
  }
  EXPECT_GT(checked, 3);
}

// The references are the clean offsets of model/path/path_generator on the same
// surface: the SPO tip is R off rail 0 along the normal, with no bump or
// noise, and the DPO axis is a unit vector; both carry the case's cutter.
TEST(RandomCasesTest, ReferencesAreCleanOffsets) {
  const std::vector<Machine> machines = testing::SharedMachines();
  for (unsigned seed = 1; seed <= 10; ++seed) {
    RandomCase c;
    ASSERT_TRUE(MakeRandomCase(seed, RandomCaseOptions(), machines, &c).ok());
    SCOPED_TRACE(c.description);
    ASSERT_EQ(c.clean_spo.poses.size(), 60u);
    ASSERT_EQ(c.clean_dpo.poses.size(), 60u);
    for (size_t i = 0; i < 60; ++i) {
      const double u = i / 59.0;
      const Eigen::Vector3d c1 = c.surface.rail(0).Point(u);
      const ToolPose& spo = c.clean_spo.poses[i];
      EXPECT_NEAR(
          SignedDistanceToFlank<double>(c.cutter, c1, spo.p_w_tip, spo.a_w),
          0.0, 1e-9);
      EXPECT_NEAR((c1 - spo.p_w_tip).dot(spo.a_w), 0.0, 1e-9);
      EXPECT_NEAR(c.clean_dpo.poses[i].a_w.norm(), 1.0, 1e-12);
    }
    EXPECT_EQ(c.clean_dpo.cutter->radius_mm, c.cutter.radius_mm);
  }
}

}  // namespace
}  // namespace tpopt
