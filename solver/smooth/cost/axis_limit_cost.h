// One-sided penalty on the machine's axis limits at the programmed feed:
// the k-th time derivative (k = 1 velocity, 2 acceleration, 3 jerk) of each
// joint X, Y, Z (machine coordinates, through the kinematics), A and C, from
// k + 1 consecutive poses at their planned times t_j:
//   D = sum_j c_j J_j                    (divided differences over t_j)
//   r_axis = sqrt(w h / L) * max(0, |D| - m lim) / lim
// zero inside m * lim (m < 1 is a safety margin, so that the resampled
// output also stays inside), one-sided and dimensionless; axes without a
// limit give 0. h is the stencil's mean arc-length step and L the path
// length, as in the other families; w is dimensionless. The times come from
// the initial path at the programmed feed and stay fixed during the solve.
#ifndef TPOPT_SOLVER_AXIS_LIMIT_COST_H_
#define TPOPT_SOLVER_AXIS_LIMIT_COST_H_

#include <array>
#include <cmath>

#include <ceres/ceres.h>

#include "model/machine/machine.h"
#include "solver/smooth/cost/divided_difference.h"
#include "solver/smooth/cost/pose_parameters.h"
#include "solver/smooth/cost/pose_stencil.h"

namespace tpopt {

template <int kOrder>
class AxisLimitCost : public PoseStencil<AxisLimitCost<kOrder>> {
 public:
  static_assert(kOrder >= 1 && kOrder <= 3, "velocity, acceleration or jerk");

  // t_s: planned times of the k + 1 poses; limits: per axis (index Axis), in
  // mm or rad per s^k, infinite for none.
  AxisLimitCost(const std::array<double, kOrder + 1>& t_s, const std::array<double, 5>& limits,
                const KinematicParams& kinematics, double scale, double margin)
      : weights_(DerivativeWeights<kOrder>(t_s)),
        limits_(limits),
        kinematics_(kinematics),
        scale_(scale),
        margin_(margin) {}

  static ceres::CostFunction* Create(const std::array<double, kOrder + 1>& t_s,
                                     const std::array<double, 5>& limits,
                                     const KinematicParams& kinematics, double scale,
                                     double margin) {
    auto* f = new AxisLimitCost(t_s, limits, kinematics, scale, margin);
    constexpr int P = kPoseSize;
    if constexpr (kOrder == 1) {
      return new ceres::AutoDiffCostFunction<AxisLimitCost, 5, P, P>(f);
    } else if constexpr (kOrder == 2) {
      return new ceres::AutoDiffCostFunction<AxisLimitCost, 5, P, P, P>(f);
    } else {
      return new ceres::AutoDiffCostFunction<AxisLimitCost, 5, P, P, P, P>(f);
    }
  }

  // Residuals from the k + 1 poses (PoseStencil calls this).
  template <typename T>
  bool Evaluate(const T* const* poses, T* r) const {
    Eigen::Matrix<T, 5, 1> derivative = Eigen::Matrix<T, 5, 1>::Zero();
    for (int j = 0; j <= kOrder; ++j) {
      derivative += weights_[j] * PoseJoints(kinematics_, poses[j]);
    }
    for (int a = 0; a < 5; ++a) {
      r[a] = T(0.0);
      if (!std::isfinite(limits_[a])) continue;
      using std::abs;
      const T excess = abs(derivative[a]) - T(margin_ * limits_[a]);
      if (excess > T(0.0)) r[a] = T(scale_ / limits_[a]) * excess;
    }
    return true;
  }

 private:
  std::array<double, kOrder + 1> weights_;
  std::array<double, 5> limits_;
  KinematicParams kinematics_;
  double scale_;
  double margin_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_AXIS_LIMIT_COST_H_
