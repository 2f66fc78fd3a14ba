// Several cost functions of one pose's parameter block as one residual
// block, their rows one after another in the order added.
//
// Every residual block costs Ceres its own evaluation, Jacobian block and
// normal-matrix product, and the walls and the tip gauge are one small
// block each at every free pose: on BM_HighAccuracy/10000 the walls' 10,000
// blocks of three rows, which hardly ever act, were 9 % of the solve. Stacked
// with the pose's deviation block they cost only their rows. The block's
// value and Jacobian are the parts' stacked, so the problem is the same.
#ifndef TPOPT_SOLVER_STACKED_COST_H_
#define TPOPT_SOLVER_STACKED_COST_H_

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <memory>
#include <vector>

#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class StackedCost : public ceres::CostFunction {
 public:
  StackedCost() { mutable_parameter_block_sizes()->push_back(kPoseSize); }

  // Takes `part` over; it must have one parameter block, a pose.
  void Add(std::unique_ptr<ceres::CostFunction> part) {
    CHECK_EQ(part->parameter_block_sizes().size(), 1u);
    CHECK_EQ(part->parameter_block_sizes()[0], kPoseSize);
    set_num_residuals(num_residuals() + part->num_residuals());
    parts_.push_back(std::move(part));
  }

  size_t parts() const { return parts_.size(); }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
    for (const std::unique_ptr<ceres::CostFunction>& part : parts_) {
      double* part_jacobians[1] = {jacobian};
      if (!part->Evaluate(parameters, residuals, jacobian != nullptr ? part_jacobians : nullptr)) {
        return false;
      }
      residuals += part->num_residuals();
      if (jacobian != nullptr) jacobian += part->num_residuals() * kPoseSize;
    }
    return true;
  }

  // Part k's share of the block's cost at `pose`, 1/2 |r_k|^2 as Ceres
  // counts it.
  double PartCost(size_t k, const double* pose) const {
    std::vector<double> r(parts_[k]->num_residuals());
    const double* parameters[1] = {pose};
    if (!parts_[k]->Evaluate(parameters, r.data(), nullptr)) return 0.0;
    double cost = 0.0;
    for (double x : r) cost += 0.5 * x * x;
    return cost;
  }

 private:
  std::vector<std::unique_ptr<ceres::CostFunction>> parts_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_STACKED_COST_H_
