// Removes the gauge freedom of the flank distance: sliding the tip along its
// own axis changes no flank distance, so the tip is held at the height of its
// contact point on rail 0 (the bottom of the cut):
//   h = (C1(u_i) - p_w_tip) . a_w                                    [mm]
//   r = sqrt(w h_s / L) * h / tol
// with h_s the arc-length step of the pose and L the path length, as in the
// other families; w is dimensionless.
#ifndef TPOPT_SOLVER_TIP_HEIGHT_COST_H_
#define TPOPT_SOLVER_TIP_HEIGHT_COST_H_

#include <ceres/ceres.h>

#include "solver/pose_parameters.h"

namespace tpopt {

class TipHeightCost {
 public:
  // contact_w: C1(u_i) in W; scale = sqrt(w h_s / L) / tol.
  TipHeightCost(const Eigen::Vector3d& contact_w, double scale)
      : contact_w_(contact_w), scale_(scale) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    r[0] = T(scale_) * (contact_w_.cast<T>() - PoseTip(pose)).dot(PoseAxis(pose));
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& contact_w, double scale) {
    return new ceres::AutoDiffCostFunction<TipHeightCost, 1, kPoseSize>(
        new TipHeightCost(contact_w, scale));
  }

 private:
  Eigen::Vector3d contact_w_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TIP_HEIGHT_COST_H_
