#include "solver/smooth/cost/travel_cost.h"

#include <gtest/gtest.h>

#include <random>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(TravelCostTest, ZeroInsideTheTravelLessTheMarginAndLinearBeyond) {
  Machine machine;
  ASSERT_TRUE(ReadMachineJson(testing::SourcePath(
                                  "data/machines/linuxcnc_xyzac_trt_sim.json"),
                              &machine)
                  .ok());
  const std::array<double, 3> lo = {-200, -100, -120}, hi = {200, 100, 120};
  std::unique_ptr<ceres::CostFunction> cost(
      TravelCost::Create(machine.kinematics, lo, hi, 0.5, 2.0));
  // Poses at A = 0.3, C = 0.7 whose joints are placed by the inverse
  // kinematics: the residual is the closed form of each joint.
  const double A = 0.3, C = 0.7;
  for (const Eigen::Vector3d& xyz :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(199.4, -99.6, 119.4),
        Eigen::Vector3d(199.75, 0, 0), Eigen::Vector3d(0, -101, 0),
        Eigen::Vector3d(5, 5, 130)}) {
    const Eigen::Vector3d p_w = JointsToWorkpiece<double>(
        machine.kinematics, xyz.x(), xyz.y(), xyz.z(), A, C);
    std::array<double, 5> pose = {A, C, p_w.x(), p_w.y(), p_w.z()};
    const double* params[] = {pose.data()};
    double r[3];
    ASSERT_TRUE(cost->Evaluate(params, r, nullptr));
    for (int j = 0; j < 3; ++j) {
      const double over = std::max(0.0, xyz[j] - (hi[j] - 0.5)) +
                          std::max(0.0, (lo[j] + 0.5) - xyz[j]);
      EXPECT_NEAR(r[j], 2.0 * over / 0.5, 1e-9)
          << j << " at " << xyz.transpose();
    }
  }
}

TEST(TravelCostTest,
     JacobiansMatchNumericDifferencesAtRandomPosesAndNearThePole) {
  Machine machine;
  ASSERT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"),
                      &machine)
          .ok());
  // A travel small enough that every random pose lies beyond it somewhere,
  // and one axis without a limit.
  const std::array<double, 3> lo = {-1, -kInf, -2}, hi = {1, kInf, 2};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double a = trial == 0 ? 0.0 : trial == 1 ? 1e-6 : 1.5 * unit(rng);
    std::array<double, 5> pose = {a, 3 * unit(rng), 50 * unit(rng),
                                  50 * unit(rng), 50 * unit(rng)};
    testing::ExpectJacobiansMatchNumeric(
        TravelCost::Create(machine.kinematics, lo, hi, 0.5, 1.3),
        {pose.data()});
  }
}

}  // namespace
}  // namespace tpopt
