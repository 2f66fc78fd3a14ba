#include "solver/smooth/cost/surface_side_cost.h"

#include <gtest/gtest.h>

#include <random>

#include "model/machine/machine.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

// The plane z = 0 with the cutter above it (+z); the ruling along y from
// (0, 0, 0) to (0, 30, 0); R = 4.
std::array<SurfaceSideCost::End, 2> PlaneEnds() {
  std::array<SurfaceSideCost::End, 2> ends;
  ends[0] = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1), 4.0};
  ends[1] = {Eigen::Vector3d(0, 30, 0), Eigen::Vector3d(0, 0, 1), 4.0};
  return ends;
}

std::array<double, 2> Residuals(ceres::CostFunction* cost,
                                const std::array<double, 5>& pose) {
  const double* params[] = {pose.data()};
  std::array<double, 2> r = {-1, -1};
  EXPECT_TRUE(cost->Evaluate(params, r.data(), nullptr));
  return r;
}

TEST(SurfaceSideCostTest, ZeroForAFlankPoseAndTheClosedFormOnTheWrongSide) {
  std::unique_ptr<ceres::CostFunction> cost(
      SurfaceSideCost::Create(PlaneEnds(), 1.0));
  // Axis along +y (A = 90 deg, C = 0), R above the ruling, tip 2 mm below
  // the floor: a flank pose, no cost whatever the overhang.
  const double a = M_PI / 2;
  for (double overhang : {0.0, 2.0, -1.0}) {
    const auto r = Residuals(cost.get(), {a, 0.0, 0, -overhang, 4});
    EXPECT_NEAR(r[0], 0.0, 1e-12);
    EXPECT_NEAR(r[1], 0.0, 1e-12);
  }
  // The mirror pose R below the surface: the flank distance is the same,
  // the side is not: r = (R/2 + R) / R = 1.5 at both ends.
  auto r = Residuals(cost.get(), {a, 0.0, 0, 0, -4});
  EXPECT_NEAR(r[0], 1.5, 1e-12);
  EXPECT_NEAR(r[1], 1.5, 1e-12);
  // An axis lying across the surface: from (0, 0, 4) down through the
  // plane, reaching z = -4 level with the far end (30 mm on): only the far
  // end is on the wrong side.
  const Eigen::Vector3d dir = Eigen::Vector3d(0, 30, -8).normalized();
  const double across_a = std::acos(dir.z()),
               across_c = std::atan2(dir.x(), dir.y());
  r = Residuals(cost.get(), {across_a, across_c, 0, 0, 4});
  // Level with q at y: the axis point's height is 4 - 8 (y / 30) cos... by
  // projection: x = p + ((q - p) . a) a, d = x_z.
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d p(0, 0, 4), q(0, 30.0 * k, 0);
    const double d = (p + (q - p).dot(dir) * dir).z();
    EXPECT_NEAR(r[k], std::max(0.0, 2.0 - d) / 4.0, 1e-12) << k;
  }
  EXPECT_EQ(r[0], 0.0);
  EXPECT_GT(r[1], 1.0);
}

TEST(SurfaceSideCostTest,
     JacobiansMatchNumericDifferencesAtRandomPosesAndNearThePole) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    std::array<SurfaceSideCost::End, 2> ends;
    for (auto& end : ends) {
      end.q_w = 20 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      end.normal_w =
          Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
      end.radius_mm = 3 + unit(rng);
    }
    // Poses on the wrong side of both ends' planes, where the walls act;
    // the first two at the pole and next to it.
    const double a = trial == 0 ? 0.0 : trial == 1 ? 1e-6 : 1.5 * unit(rng);
    std::array<double, 5> pose = {a, 3 * unit(rng), 0, 0, 0};
    const Eigen::Vector3d tip = 0.5 * (ends[0].q_w + ends[1].q_w) -
                                8 * (ends[0].normal_w + ends[1].normal_w);
    for (int k = 0; k < 3; ++k) pose[kPoseTip + k] = tip[k];
    testing::ExpectJacobiansMatchNumeric(SurfaceSideCost::Create(ends, 0.8),
                                         {pose.data()});
  }
}

}  // namespace
}  // namespace tpopt
