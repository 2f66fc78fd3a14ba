#include "solver/smooth/cost/wall_cost.h"

#include <gtest/gtest.h>

#include <random>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Fixture {
  Machine machine;
  std::array<double, 3> lo = {-20, -kInf, -15}, hi = {20, kInf, 15};
  Eigen::Vector3d a0_w = AnglesToAxis(0.5, 0.2);
  double cone_rad = 12 * M_PI / 180;
  // The plane z = 0, cutter above it, ruling along y (surface_side_cost_test).
  std::array<SurfaceSideCost::End, 2> ends = {
      SurfaceSideCost::End{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1),
                           4.0},
      SurfaceSideCost::End{Eigen::Vector3d(0, 30, 0), Eigen::Vector3d(0, 0, 1),
                           4.0}};
  double scale = 1.7;

  WallCost::Walls All() const {
    WallCost::Walls walls;
    walls.travel.emplace(machine.kinematics, lo, hi, 0.5, scale);
    walls.cone.emplace(a0_w, cone_rad, scale);
    walls.side.emplace(ends, scale);
    return walls;
  }
};

Fixture MakeFixture() {
  Fixture f;
  EXPECT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"),
                      &f.machine)
          .ok());
  return f;
}

// Residuals and row-major Jacobian (rows x 5) of a cost at a pose.
void Evaluate(const ceres::CostFunction& cost,
              const std::array<double, 5>& pose, std::vector<double>* r,
              std::vector<double>* j) {
  r->assign(cost.num_residuals(), -1.0);
  j->assign(cost.num_residuals() * kPoseSize, -1.0);
  const double* params[] = {pose.data()};
  double* jacobians[] = {j->data()};
  ASSERT_TRUE(cost.Evaluate(params, r->data(), jacobians));
}

TEST(WallCostTest, EqualsTheThreeWallsStackedValueAndJacobianInsideAndBeyond) {
  const Fixture f = MakeFixture();
  const WallCost merged(f.All());
  ASSERT_EQ(merged.num_residuals(), 6);
  std::unique_ptr<ceres::CostFunction> travel(
      TravelCost::Create(f.machine.kinematics, f.lo, f.hi, 0.5, f.scale));
  std::unique_ptr<ceres::CostFunction> cone(
      AxisConeCost::Create(f.a0_w, f.cone_rad, f.scale));
  std::unique_ptr<ceres::CostFunction> side(
      SurfaceSideCost::Create(f.ends, f.scale));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  int active[3] = {0, 0, 0}, quiet = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Axes round the cone's edge, tips round the travel's and the plane's.
    const std::array<double, 5> pose = {0.5 + 0.4 * unit(rng),
                                        0.2 + 0.4 * unit(rng), 25 * unit(rng),
                                        40 * unit(rng), 6 * unit(rng)};
    std::vector<double> r, j;
    Evaluate(merged, pose, &r, &j);
    int row = 0, index = 0;
    bool any = false;
    for (const ceres::CostFunction* wall :
         {travel.get(), cone.get(), side.get()}) {
      std::vector<double> wr, wj;
      Evaluate(*wall, pose, &wr, &wj);
      bool acts = false;
      for (int k = 0; k < wall->num_residuals(); ++k) {
        EXPECT_EQ(r[row + k], wr[k]) << "trial " << trial << " row " << row + k;
        acts = acts || wr[k] != 0.0;
        for (int c = 0; c < kPoseSize; ++c) {
          EXPECT_EQ(j[(row + k) * kPoseSize + c], wj[k * kPoseSize + c])
              << "trial " << trial << " row " << row + k << " column " << c;
        }
      }
      active[index++] += acts;
      any = any || acts;
      row += wall->num_residuals();
    }
    quiet += !any;
  }
  // The draw reaches every wall and leaves some poses inside all of them.
  EXPECT_GT(active[0], 10);
  EXPECT_GT(active[1], 10);
  EXPECT_GT(active[2], 10);
  EXPECT_GT(quiet, 10);
}

TEST(WallCostTest, JacobiansMatchNumericDifferencesWhereWallsAct) {
  const Fixture f = MakeFixture();
  // Beyond the X travel, outside the cone, and R below the plane at once.
  std::array<double, 5> beyond = {0.5 + 0.5, 0.2, 30, 10, -4};
  testing::ExpectJacobiansMatchNumeric(new WallCost(f.All()), {beyond.data()});
  // Near the pole, outside the cone and beyond the Z travel (the plane's
  // wall is left out: an upright axis lies in it, where its derivative in z
  // is 1 - a_z^2 ~ 1e-12, below what numeric differences resolve).
  WallCost::Walls walls = f.All();
  walls.side.reset();
  std::array<double, 5> pole = {1e-6, 0.4, 0, 10, 16};
  testing::ExpectJacobiansMatchNumeric(new WallCost(walls), {pole.data()});
}

TEST(WallCostTest,
     AbsentWallsHaveNoRowsAndTheTravelAloneServesASurfaceFreeRun) {
  const Fixture f = MakeFixture();
  WallCost::Walls walls;
  walls.travel.emplace(f.machine.kinematics, f.lo, f.hi, 0.5, f.scale);
  const WallCost travel_only(walls);
  ASSERT_EQ(travel_only.num_residuals(), 3);
  // X = 20.5 mm past hi - margin = 19.5 by 1 mm: r = 1.7 * 1 / 0.5.
  const Eigen::Vector3d p_w =
      JointsToWorkpiece<double>(f.machine.kinematics, 20.5, 0.0, 0.0, 0.3, 0.1);
  const std::array<double, 5> pose = {0.3, 0.1, p_w.x(), p_w.y(), p_w.z()};
  std::vector<double> r, j;
  Evaluate(travel_only, pose, &r, &j);
  EXPECT_NEAR(r[0], 1.7 * 1.0 / 0.5, 1e-9);
  EXPECT_EQ(r[1], 0.0);
  EXPECT_EQ(r[2], 0.0);
  // Rows of walls that do not act are exactly zero in the Jacobian.
  for (int c = 0; c < kPoseSize; ++c) {
    EXPECT_EQ(j[1 * kPoseSize + c], 0.0);
    EXPECT_EQ(j[2 * kPoseSize + c], 0.0);
  }
  EXPECT_NE(j[0 * kPoseSize + kPoseTip], 0.0);
  // Residuals only (no Jacobian asked for).
  const double* params[] = {pose.data()};
  double only[3] = {-1, -1, -1};
  EXPECT_TRUE(travel_only.Evaluate(params, only, nullptr));
  EXPECT_NEAR(only[0], r[0], 1e-15);
}

}  // namespace
}  // namespace tpopt
