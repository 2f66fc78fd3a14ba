// Every residual functor of the high-accuracy problem (solver/*_cost.h)
// against central differences of its own residuals, in manif's manner: at
// random poses (fixed seed), at the A = 0 pole and near it
// (|A| = 1e-6 .. 1e-3 rad, both signs), where the axis no longer depends
// on C and a careless derivative through the kinematics would show.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "solver/smooth/cost/axis_cone_cost.h"
#include "solver/smooth/cost/axis_limit_cost.h"
#include "solver/smooth/cost/deviation_cost.h"
#include "solver/smooth/cost/smoothness_cost.h"
#include "solver/smooth/cost/surface_side_cost.h"
#include "solver/smooth/cost/tip_height_cost.h"
#include "solver/smooth/cost/tolerance_band_cost.h"
#include "solver/smooth/cost/travel_cost.h"

namespace tpopt {
namespace {

using Pose = std::array<double, kPoseSize>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The A values every family is checked at besides the random ones.
const std::vector<double> kPoleAngles = {0.0,   1e-6,  -1e-6, 1e-5, -1e-5,
                                         1e-4,  -1e-4, 1e-3,  -1e-3};
constexpr int kRandomDraws = 50;

// Columns checked and columns skipped because a kink of a one-sided
// penalty lies within the difference step (the two step sizes disagree).
struct Tally {
  int columns = 0;
  int skipped = 0;
};

std::vector<double> Residuals(const ceres::CostFunction& cost, const std::vector<Pose>& poses) {
  std::vector<const double*> params;
  for (const Pose& p : poses) params.push_back(p.data());
  std::vector<double> r(cost.num_residuals());
  EXPECT_TRUE(cost.Evaluate(params.data(), r.data(), nullptr));
  return r;
}

// Central differences of the residuals in one parameter, step h.
std::vector<double> CentralDifference(const ceres::CostFunction& cost, std::vector<Pose> poses,
                                      int block, int column, double h) {
  const double x = poses[block][column];
  poses[block][column] = x + h;
  const std::vector<double> plus = Residuals(cost, poses);
  poses[block][column] = x - h;
  const std::vector<double> minus = Residuals(cost, poses);
  std::vector<double> d(plus.size());
  for (size_t i = 0; i < d.size(); ++i) d[i] = (plus[i] - minus[i]) / (2 * h);
  return d;
}

// Takes ownership of `cost`. The analytic Jacobian must match the central
// difference to 1e-6 relative (1e-6 absolute below 1) in every column
// where steps h and 4h agree (no kink between them).
void ExpectJacobianMatchesDifferences(ceres::CostFunction* cost_raw,
                                      const std::vector<Pose>& poses, const std::string& where,
                                      Tally* tally) {
  std::unique_ptr<ceres::CostFunction> cost(cost_raw);
  ASSERT_EQ(cost->parameter_block_sizes().size(), poses.size()) << where;
  const int m = cost->num_residuals();
  std::vector<const double*> params;
  for (const Pose& p : poses) params.push_back(p.data());
  std::vector<std::vector<double>> jac(poses.size(), std::vector<double>(m * kPoseSize));
  std::vector<double*> jac_ptrs;
  for (auto& j : jac) jac_ptrs.push_back(j.data());
  std::vector<double> r(m);
  ASSERT_TRUE(cost->Evaluate(params.data(), r.data(), jac_ptrs.data())) << where;
  for (size_t b = 0; b < poses.size(); ++b) {
    for (int c = 0; c < kPoseSize; ++c) {
      const double h = 1e-6 * std::max(1.0, std::abs(poses[b][c]));
      const std::vector<double> fd = CentralDifference(*cost, poses, b, c, h);
      const std::vector<double> fd4 = CentralDifference(*cost, poses, b, c, 4 * h);
      ++tally->columns;
      bool kink = false;
      for (int i = 0; i < m; ++i) {
        if (std::abs(fd[i] - fd4[i]) > 1e-5 * std::max(1.0, std::abs(fd[i]))) kink = true;
      }
      if (kink) {
        ++tally->skipped;
        continue;
      }
      for (int i = 0; i < m; ++i) {
        const double analytic = jac[b][i * kPoseSize + c];
        EXPECT_NEAR(analytic, fd[i], 1e-6 * std::max(1.0, std::abs(fd[i])))
            << where << ": residual " << i << ", block " << b << ", parameter " << c;
      }
    }
  }
}

class Draws {
 public:
  explicit Draws(unsigned seed) : rng_(seed) {}
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  // A pose with the given A (NaN: random in [-1.5, 1.5] rad), C in
  // [-pi, pi] and the tip in [-40, 40]^3 mm.
  Pose RandomPose(double a_rad) {
    return {std::isnan(a_rad) ? Uniform(-1.5, 1.5) : a_rad, Uniform(-M_PI, M_PI),
            Uniform(-40, 40), Uniform(-40, 40), Uniform(-40, 40)};
  }
  // A near the given pose: every parameter moved a little.
  Pose Neighbour(const Pose& p, double step) {
    Pose q = p;
    for (int k = 0; k < kPoseSize; ++k) q[k] += Uniform(-step, step) * (k < kPoseTip ? 0.1 : 1);
    return q;
  }
  Eigen::Vector3d UnitVector() {
    Eigen::Vector3d v(Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1));
    while (v.norm() < 0.1) v = Eigen::Vector3d(Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1));
    return v.normalized();
  }

 private:
  std::mt19937 rng_;
};

KinematicParams Kinematics() {
  KinematicParams k;
  k.rotary_pivot_mm = Eigen::Vector3d(3.0, -2.0, 5.0);
  k.y_offset_mm = 20.0;
  k.z_offset_mm = 10.0;
  k.tool_length_mm = 7.0;
  return k;
}

// Runs `check(draws, a_rad, where, tally)` at the pole angles and at
// kRandomDraws random ones, and bounds the share of columns skipped.
void ForEachDraw(unsigned seed,
                 const std::function<void(Draws*, double, const std::string&, Tally*)>& check) {
  Draws draws(seed);
  Tally tally;
  for (double a : kPoleAngles) check(&draws, a, "A = " + std::to_string(a), &tally);
  for (int k = 0; k < kRandomDraws; ++k) check(&draws, NAN, "draw " + std::to_string(k), &tally);
  EXPECT_GT(tally.columns, 0);
  EXPECT_LE(tally.skipped, tally.columns / 20) << "too many columns near a kink";
}

TEST(CostJacobianPropertyTest, AxisCone) {
  ForEachDraw(1, [](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p = d->RandomPose(a);
    // The cone round an axis up to 0.5 rad away, half angle 0.2 rad: the
    // wall is active in most draws.
    const Pose start = d->Neighbour(p, 5.0);
    ExpectJacobianMatchesDifferences(
        AxisConeCost::Create(AnglesToAxis(start[kPoseA], start[kPoseC]), 0.2, 1.7), {p}, where,
        t);
  });
}

TEST(CostJacobianPropertyTest, AxisLimitVelocityAccelerationAndJerk) {
  const std::array<double, 5> limits = {1.0, kInf, 2.0, 0.5, 0.7};  // Y unlimited
  ForEachDraw(2, [&](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p0 = d->RandomPose(a);
    const Pose p1 = d->Neighbour(p0, 1.0), p2 = d->Neighbour(p1, 1.0), p3 = d->Neighbour(p2, 1.0);
    const double t0 = d->Uniform(0, 1);
    const std::array<double, 4> ts = {t0, t0 + 0.1, t0 + 0.25, t0 + 0.32};  // uneven
    ExpectJacobianMatchesDifferences(
        AxisLimitCost<1>::Create({ts[0], ts[1]}, limits, Kinematics(), 1.3, 0.95), {p0, p1},
        where + ", velocity", t);
    ExpectJacobianMatchesDifferences(
        AxisLimitCost<2>::Create({ts[0], ts[1], ts[2]}, limits, Kinematics(), 1.3, 0.95),
        {p0, p1, p2}, where + ", acceleration", t);
    ExpectJacobianMatchesDifferences(
        AxisLimitCost<3>::Create(ts, limits, Kinematics(), 1.3, 0.95), {p0, p1, p2, p3},
        where + ", jerk", t);
  });
}

// Contact and guard points scattered round the pose's flank, from 0.3 mm
// inside to 0.3 mm outside it, so both signs of the deviation (and the
// overcut weight) occur.
DeviationCost::Points PointsAroundFlank(Draws* d, const Pose& p, const Cutter& cutter) {
  const Eigen::Vector3d tip = PoseTip(p.data()), axis = PoseAxis(p.data());
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  DeviationCost::Points points;
  for (int k = 0; k < 6; ++k) {
    const double phi = d->Uniform(-M_PI, M_PI);
    const Eigen::Vector3d q = tip + d->Uniform(2, 30) * axis +
                              (cutter.radius_mm + d->Uniform(-0.3, 0.3)) *
                                  (std::cos(phi) * e1 + std::sin(phi) * e2);
    (k < 4 ? points.contact_w : points.guard_w).push_back(q);
  }
  return points;
}

DeviationCost::Settings DeviationSettings(Interpolation interpolation) {
  DeviationCost::Settings s;
  s.cutter.radius_mm = 4.0;
  s.cutter.flute_length_mm = 40.0;
  s.kinematics = Kinematics();
  s.tolerance_mm = 0.01;
  s.overcut_factor = 3.0;
  s.interpolation = interpolation;
  return s;
}

TEST(CostJacobianPropertyTest, DeviationAtAPose) {
  ForEachDraw(3, [](Draws* d, double a, const std::string& where, Tally* t) {
    const DeviationCost::Settings settings = DeviationSettings(Interpolation::kJoint);
    const Pose p = d->RandomPose(a);
    ExpectJacobianMatchesDifferences(
        DeviationCost::CreateAtPose(PointsAroundFlank(d, p, settings.cutter), settings, 0.4),
        {p}, where, t);
  });
}

TEST(CostJacobianPropertyTest, DeviationBetweenPosesJointAndTcp) {
  for (Interpolation interpolation : {Interpolation::kJoint, Interpolation::kTcp}) {
    ForEachDraw(4, [&](Draws* d, double a, const std::string& where, Tally* t) {
      const DeviationCost::Settings settings = DeviationSettings(interpolation);
      const Pose p0 = d->RandomPose(a), p1 = d->Neighbour(p0, 0.5);
      // The points round the mid-move pose.
      Eigen::Matrix<double, 5, 1> j0 = PoseJoints(settings.kinematics, p0.data()),
                                  j1 = PoseJoints(settings.kinematics, p1.data());
      Eigen::Vector3d tip, axis;
      InterpolateMove<double>(settings.kinematics, interpolation, j0, j1, PoseTip(p0.data()),
                              PoseTip(p1.data()), 0.37, &tip, &axis);
      const auto angles = AxisToAngles(axis);
      const Pose mid = {angles[0][0], angles[0][1], tip.x(), tip.y(), tip.z()};
      ExpectJacobianMatchesDifferences(
          DeviationCost::CreateBetweenPoses(PointsAroundFlank(d, mid, settings.cutter),
                                            settings, 0.4, 0.37),
          {p0, p1}, where + ", " + InterpolationName(interpolation), t);
    });
  }
}

TEST(CostJacobianPropertyTest, SmoothnessSecondAndThird) {
  ForEachDraw(5, [](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p0 = d->RandomPose(a);
    const Pose p1 = d->Neighbour(p0, 1.0), p2 = d->Neighbour(p1, 1.0), p3 = d->Neighbour(p2, 1.0);
    const double s0 = d->Uniform(0, 100);
    const std::array<double, 4> s = {s0, s0 + 0.7, s0 + 1.1, s0 + 2.3};  // uneven
    ExpectJacobianMatchesDifferences(
        SmoothnessCost<2>::Create({s[0], s[1], s[2]}, 120.0, 300.0, 0.01), {p0, p1, p2},
        where + ", second", t);
    ExpectJacobianMatchesDifferences(SmoothnessCost<3>::Create(s, 120.0, 3000.0, 0.5),
                                     {p0, p1, p2, p3}, where + ", third", t);
  });
}

TEST(CostJacobianPropertyTest, SurfaceSide) {
  ForEachDraw(6, [](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p = d->RandomPose(a);
    const Eigen::Vector3d tip = PoseTip(p.data()), axis = PoseAxis(p.data());
    std::array<SurfaceSideCost::End, 2> ends;
    for (SurfaceSideCost::End& end : ends) {
      // A ruling end a few mm from the axis, its normal at random: the
      // shortfall is positive in about half the draws.
      end.q_w = tip + d->Uniform(0, 30) * axis + 4.0 * d->UnitVector();
      end.normal_w = d->UnitVector();
      end.radius_mm = d->Uniform(2, 6);
    }
    ExpectJacobianMatchesDifferences(SurfaceSideCost::Create(ends, 0.8), {p}, where, t);
  });
}

TEST(CostJacobianPropertyTest, TipHeight) {
  ForEachDraw(7, [](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p = d->RandomPose(a);
    const Eigen::Vector3d contact(d->Uniform(-40, 40), d->Uniform(-40, 40), d->Uniform(-40, 40));
    ExpectJacobianMatchesDifferences(TipHeightCost::Create(contact, d->Uniform(-3, 3), 2.0), {p},
                                     where, t);
  });
}

TEST(CostJacobianPropertyTest, ToleranceBand) {
  ForEachDraw(8, [](Draws* d, double a, const std::string& where, Tally* t) {
    const Pose p = d->RandomPose(a);
    const Pose start = d->Neighbour(p, 0.2);
    ToleranceBandCost::Band band;
    // The band's tip 0..0.05 mm off the pose's, beyond its 0.01 mm in most
    // draws; its axis up to 0.02 rad off, beyond 0.5 deg in most.
    band.p0_w = PoseTip(p.data()) + d->Uniform(0, 0.05) * d->UnitVector();
    band.tangent_w = d->UnitVector();
    band.a0_w = AnglesToAxis(start[kPoseA], start[kPoseC]);
    band.step_mm = 0.5;
    ExpectJacobianMatchesDifferences(ToleranceBandCost::Create(band, 1.2, 0.1), {p}, where, t);
  });
}

TEST(CostJacobianPropertyTest, Travel) {
  // A travel small enough that the random poses leave it, one axis free.
  const std::array<double, 3> lo = {-10, -kInf, -20}, hi = {10, kInf, 20};
  ForEachDraw(9, [&](Draws* d, double a, const std::string& where, Tally* t) {
    ExpectJacobianMatchesDifferences(TravelCost::Create(Kinematics(), lo, hi, 0.5, 1.3),
                                     {d->RandomPose(a)}, where, t);
  });
}

}  // namespace
}  // namespace tpopt
