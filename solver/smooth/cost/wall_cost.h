// The walls of one pose as one residual block: the X/Y/Z travel
// (travel_cost.h), the cone round the input's axis (axis_cone_cost.h) and
// the cutter's side of the surface (surface_side_cost.h), each optional.
//
// One block rather than one per wall: every residual block costs Ceres its
// own evaluation, Jacobian block and normal-matrix product whether or not
// its residuals vanish, and the walls act at hardly any pose. Each wall is
// one-sided, max(0, f) in form, so Evaluate first computes every wall in
// double and differentiates (automatically, with Jets) only the walls whose
// residuals are not all zero. A wall that does not act has residual 0 and
// Jacobian exactly 0 there, which is what its own AutoDiffCostFunction returns,
// so the block equals the three functors stacked, value and Jacobian.
//
// Residual rows, in order: travel (3), cone (1), side (2), each present
// only when given; at least one wall is required.
#ifndef TPOPT_SOLVER_WALL_COST_H_
#define TPOPT_SOLVER_WALL_COST_H_

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <optional>

#include "solver/smooth/cost/axis_cone_cost.h"
#include "solver/smooth/cost/pose_parameters.h"
#include "solver/smooth/cost/surface_side_cost.h"
#include "solver/smooth/cost/travel_cost.h"

namespace tpopt {

class WallCost : public ceres::CostFunction {
 public:
  struct Walls {
    std::optional<TravelCost> travel;
    std::optional<AxisConeCost> cone;
    std::optional<SurfaceSideCost> side;
  };

  explicit WallCost(const Walls& walls) : walls_(walls) {
    const int rows =
        (walls_.travel ? 3 : 0) + (walls_.cone ? 1 : 0) + (walls_.side ? 2 : 0);
    CHECK_GT(rows, 0) << "WallCost needs at least one wall";
    set_num_residuals(rows);
    mutable_parameter_block_sizes()->push_back(kPoseSize);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
    int row = 0;
    return (!walls_.travel || EvaluateWall<3>(*walls_.travel, parameters[0],
                                              residuals, jacobian, &row)) &&
           (!walls_.cone || EvaluateWall<1>(*walls_.cone, parameters[0],
                                            residuals, jacobian, &row)) &&
           (!walls_.side || EvaluateWall<2>(*walls_.side, parameters[0],
                                            residuals, jacobian, &row));
  }

 private:
  // Rows *row.. of the block from one wall; advances *row. The Jacobian by
  // forward-mode automatic differentiation (one Jet per pose parameter),
  // as AutoDiffCostFunction<Functor, kRows, kPoseSize> computes it.
  template <int kRows, typename Functor>
  static bool EvaluateWall(const Functor& functor, const double* pose,
                           double* residuals, double* jacobian, int* row) {
    double* r = residuals + *row;
    double* j = jacobian != nullptr ? jacobian + *row * kPoseSize : nullptr;
    *row += kRows;
    if (!functor(pose, r)) return false;
    if (j == nullptr) return true;
    if (std::all_of(r, r + kRows, [](double x) { return x == 0.0; })) {
      std::fill(j, j + kRows * kPoseSize, 0.0);
      return true;
    }
    using Jet = ceres::Jet<double, kPoseSize>;
    Jet pose_jets[kPoseSize], r_jets[kRows];
    for (int c = 0; c < kPoseSize; ++c) pose_jets[c] = Jet(pose[c], c);
    if (!functor(pose_jets, r_jets)) return false;
    for (int k = 0; k < kRows; ++k) {
      r[k] = r_jets[k].a;
      for (int c = 0; c < kPoseSize; ++c) j[k * kPoseSize + c] = r_jets[k].v[c];
    }
    return true;
  }

  Walls walls_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_WALL_COST_H_
